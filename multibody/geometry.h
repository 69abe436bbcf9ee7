#pragma once

#include <string>

#include <Eigen/Core>

#include <cairn/multibody/pose.h>

namespace cairn::multibody {

/// The shape kinds a body's collision or visual geometry can have.
enum class GeometryType {
  kBox,       ///< `size` holds the full side lengths (x, y, z).
  kSphere,    ///< `radius`.
  kCylinder,  ///< `radius` and `length`, axis along the geometry frame's z.
  kCapsule,   ///< `radius` and `length` of the cylindrical part, axis along z (a cylinder with hemispherical caps).
  kMesh,      ///< `mesh_path` (resolved absolute path) and `scale`.
};

/// Returns "box", "sphere", "cylinder", "capsule" or "mesh".
const char* GeometryTypeName(GeometryType type);

/// One collision or visual shape attached to a body, placed by X_BG (geometry frame G in body frame B).
struct Geometry {
  /// Name of the shape (the URDF `name` attribute, or "<link>_collision_<k>" when it has none).
  std::string name;
  /// Which kind of shape this is; decides which of the size fields are meaningful.
  GeometryType type = GeometryType::kSphere;
  /// Pose of the geometry frame in the body frame.
  Pose X_BG;
  /// Box side lengths.
  Eigen::Vector3d size = Eigen::Vector3d::Zero();
  /// Sphere, cylinder and capsule radius.
  double radius = 0.0;
  /// Cylinder and capsule length along z (for a capsule, the distance between the cap centres).
  double length = 0.0;
  /// Absolute path of a mesh file (after package:// resolution).
  std::string mesh_path;
  /// Mesh scale per axis.
  Eigen::Vector3d scale = Eigen::Vector3d::Ones();
};

}  // namespace cairn::multibody
