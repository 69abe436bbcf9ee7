#pragma once

/// @file
/// Builds a Model from a URDF file through urdfdom.

#include <string>

#include <cairn/multibody/model.h>
#include <cairn/multibody/package_map.h>

namespace cairn::multibody {

/// How ParseUrdfFile / ParseUrdfString build the model.
struct UrdfOptions {
  /// Attach the root link to the world with a quaternion floating joint (otherwise it is welded to the world).
  /// A root link called "world" is the world itself and cannot float.
  bool floating_base = false;
  /// Name of the floating joint.
  std::string floating_joint_name = "root_joint";
  /// Resolves package:// URIs. When a package is not mapped, a folder of that name holding a package.xml among
  /// the URDF's enclosing folders is used (the ROS layout).
  PackageMap packages;
  /// Require every mesh file referenced by a collision or visual element to exist.
  bool check_mesh_files = true;
};

/// Parses the URDF file at `path`. Every error (unreadable file, malformed XML, a joint naming a missing link,
/// a kinematic loop, negative or NaN mass, an inertia that is not positive definite, a zero joint axis, a
/// mimic or planar joint, a missing mesh file or unknown package) throws std::runtime_error whose message
/// starts with the file name and names the offending element.
///
/// Links become bodies, in depth-first order from the root (children in joint-name order). A `continuous`
/// joint is an unlimited revolute joint with one coordinate (the angle). A collision `<cylinder>` whose
/// collision `name` starts with "capsule" is read as a capsule (URDF has no capsule element): radius r and
/// cylinder length l between the centres of its hemispherical caps.
Model ParseUrdfFile(const std::string& path, const UrdfOptions& options = UrdfOptions());

/// Parses URDF text; relative mesh paths resolve against `base_directory`, and `source_name` stands for the
/// file in error messages.
Model ParseUrdfString(const std::string& xml, const std::string& base_directory,
                      const UrdfOptions& options = UrdfOptions(), const std::string& source_name = "<string>");

}  // namespace cairn::multibody
