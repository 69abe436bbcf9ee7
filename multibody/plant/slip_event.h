#pragma once

#include <Eigen/Core>

namespace cairn::multibody {

/// A loaded sole slid farther than ContactMonitorOptions::slip_distance at more than slip_speed.
struct SlipEvent {
  /// Time the slip was detected (s).
  double time = 0.0;
  /// 0 for the first (left) sole, 1 for the second (right).
  int foot = 0;
  /// Sole frame position at detection (world).
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  /// |F_t| / F_n at detection.
  double force_ratio = 0.0;
};

}  // namespace cairn::multibody
