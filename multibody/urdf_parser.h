#pragma once

/// @file
/// Builds a Model from a URDF file through urdfdom.

#include <string>

#include <cairn/multibody/model.h>
#include <cairn/multibody/package_map.h>
#include <cairn/multibody/urdf_xml_check.h>

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

/// Parses the URDF file at `path`. Every error (a directory or unreadable file, a file over kMaxUrdfBytes,
/// malformed XML or elements nested deeper than kMaxUrdfNestingDepth, a numeric attribute that is not exactly
/// its count of finite numbers, a joint naming a missing link, a kinematic loop, a negative mass, an inertia
/// that is not positive definite or violates the triangle inequality, a shape size <= 0, a negative effort or
/// velocity limit, a lower limit above the upper, a zero joint axis, a mimic or planar joint, a missing mesh
/// file or unknown package, more than kMaxModelBodies links) throws std::runtime_error whose message starts
/// with the file name and names the offending link or joint and value.
///
/// Links become bodies, in depth-first order from the root (children in joint-name order); the tree is walked
/// without recursion, so a chain of any length up to kMaxModelBodies loads. A `continuous`
/// joint is an unlimited revolute joint with one coordinate (the angle). A collision `<cylinder>` whose
/// collision `name` starts with "capsule" is read as a capsule (URDF has no capsule element): radius r and
/// cylinder length l between the centres of its hemispherical caps.
Model ParseUrdfFile(const std::string& path, const UrdfOptions& options = UrdfOptions());

/// Parses URDF text; relative mesh paths resolve against `base_directory`, and `source_name` stands for the
/// file in error messages.
Model ParseUrdfString(const std::string& xml, const std::string& base_directory,
                      const UrdfOptions& options = UrdfOptions(), const std::string& source_name = "<string>");

}  // namespace cairn::multibody
