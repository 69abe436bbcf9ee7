#pragma once

#include <Eigen/Core>

namespace cairn::multibody {

/// The contact of one sole with the terrain after a plant step.
struct SoleState {
  /// Total contact force on the foot (N, world frame).
  Eigen::Vector3d force = Eigen::Vector3d::Zero();
  /// Force along the mean contact normal (N).
  double normal_force = 0.0;
  /// Magnitude of the force perpendicular to the normal (N).
  double tangential_force = 0.0;
  /// Centre of pressure: the normal-force-weighted mean of the contact points (world; the sole frame's origin when
  /// there is no contact).
  Eigen::Vector3d cop = Eigen::Vector3d::Zero();
  /// normal_force > ContactMonitorOptions::loaded_force.
  bool loaded = false;
  /// Position of the sole frame (world).
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  /// Speed of the sole frame's origin tangential to the contact normal (m/s; the z axis without contact).
  double tangential_speed = 0.0;
};

}  // namespace cairn::multibody
