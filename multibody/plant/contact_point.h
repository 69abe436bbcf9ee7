#pragma once

#include <Eigen/Core>

namespace cairn::multibody {

/// One contact point between a robot body and a terrain box after a BulletPlant step, with the force the terrain
/// exerted on the robot during that step (the solver's impulse divided by the step).
struct ContactPoint {
  /// Cairn body index of the robot body in contact (for bodies merged through fixed joints: the moving body that
  /// carries them).
  int body = -1;
  /// Index of the terrain box in the plant's terrain list.
  int terrain = -1;
  /// Contact point on the terrain surface, world frame.
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  /// Unit contact normal, world frame, pointing from the terrain into the robot.
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();
  /// Normal force on the robot (N, >= 0).
  double normal_force = 0.0;
  /// Friction force on the robot (N, world frame, perpendicular to `normal`).
  Eigen::Vector3d tangential_force = Eigen::Vector3d::Zero();
  /// Signed distance between the shapes (m, negative when penetrating).
  double distance = 0.0;
};

}  // namespace cairn::multibody
