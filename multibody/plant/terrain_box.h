#pragma once

#include <limits>
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
  /// Normal contact stiffness (N/m): infinity (the default) is Bullet's rigid contact; a finite value > 0 makes
  /// the box yield like a spring of that stiffness (Bullet's per-object contact stiffness), e.g. soft soil.
  /// Bullet applies it at each contact point, so a body resting on the box at n points meets about n times the
  /// stiffness (a round probe tip touches at one point; a flat sole at up to four).
  double contact_stiffness = std::numeric_limits<double>::infinity();
  /// Normal contact damping (N s/m, finite, >= 0) of a box with a finite contact_stiffness; must stay 0 for a
  /// rigid box.
  double contact_damping = 0.0;
};

}  // namespace cairn::multibody
