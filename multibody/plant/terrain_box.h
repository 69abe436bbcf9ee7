#pragma once

#include <string>

#include <Eigen/Core>

#include <cairn/multibody/pose.h>

namespace cairn::multibody {

/// One static terrain region of a BulletPlant: a box with its own Coulomb friction coefficient, so that one
/// scene can hold ice, wood and carpet side by side. Plain boxes are the plant's terrain input (multibody must not
/// depend on planning); a planner's terrain map is turned into boxes on the planning side.
struct TerrainBox {
  /// Region name, used in error messages and contact reports.
  std::string name;
  /// Pose of the box's centre and axes in the world.
  Pose X_WB;
  /// Full side lengths (x, y, z) in metres; each must be finite and > 0.
  Eigen::Vector3d size = Eigen::Vector3d::Ones();
  /// The true Coulomb friction coefficient between this region and the robot (finite, in [0, 10]).
  double friction = 1.0;
};

}  // namespace cairn::multibody
