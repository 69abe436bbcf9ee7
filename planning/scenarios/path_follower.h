#pragma once

/// @file
/// PathFollower: a kinematic robot walking along the planned path, as a system.

#include "cairn/systems/framework/leaf_system.h"

namespace cairn::planning {

/// Every `period` seconds moves the robot `step` metres along the path on its input (from the path's first point,
/// the robot's cell), unless paused (the probing planner stands the robot still while it probes).
///
/// | port | type | meaning |
/// |---|---|---|
/// | input `path` | Eigen::Matrix2Xd | the plan (GridPathPlanner's `path`) |
/// | input `pause` | vector of size 1 | >= 0.5: stand still |
/// | output `position` | vector of size 2 | the robot's x-y (the discrete state) |
class PathFollower final : public systems::LeafSystem {
 public:
  PathFollower(const Eigen::Vector2d& start, double step, double period);

  const systems::InputPort& get_path_input_port() const { return get_input_port(0); }
  const systems::InputPort& get_pause_input_port() const { return get_input_port(1); }
  const systems::OutputPort& get_position_output_port() const { return get_output_port(0); }

 private:
  double step_;
};

}  // namespace cairn::planning
