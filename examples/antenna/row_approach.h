#pragma once

/// @file
/// RowApproach: the sensor pose of a robot visiting a row of objects, one view per frame period.

#include <Eigen/Geometry>

#include "cairn/systems/framework/leaf_system.h"

namespace cairn::examples {

/// The objects stand along x_W every `spacing` metres from x = 0. The robot looks at object i for
/// `frames_per_object` frame periods, from a distance and heading that change each frame (0.6–0.8 m, within
/// ±0.5 rad), then moves on to the next; after the last object it starts the row again. The pose is constant
/// within a frame period.
///
/// | port | type | meaning |
/// |---|---|---|
/// | output `X_WC` | Eigen::Isometry3d | the sensor pose (depends on time only) |
class RowApproach final : public systems::LeafSystem {
 public:
  /// Throws std::invalid_argument for a non-positive period, spacing or count.
  RowApproach(int objects, int frames_per_object, double spacing, double sensor_height, double period);

  /// The object the robot looks at at time t, and the pose.
  int ObjectAt(double t) const;
  Eigen::Isometry3d PoseAt(double t) const;

  const systems::OutputPort& get_pose_output_port() const { return get_output_port(0); }

 private:
  int objects_;
  int frames_per_object_;
  double spacing_;
  double sensor_height_;
  double period_;
};

}  // namespace cairn::examples
