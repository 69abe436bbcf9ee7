#pragma once

/// @file
/// ScenarioSensor: a TraverseScenario's ground as a depth sensor and segmenter would see it, as a system.

#include "cairn/planning/scenarios/traverse_scenario.h"
#include "cairn/systems/framework/leaf_system.h"

namespace cairn::planning {

/// The ground within the scenario's sensor range of the robot, sampled on the scenario's lattice, with per-point
/// class probabilities (the true class at segmentation_confidence). Noise-free, so that the output is a pure
/// function of the input (TraverseSimulation adds the D435 noise in its own loop).
///
/// | port | type | meaning |
/// |---|---|---|
/// | input `robot` | vector of size 2 | the robot's x-y |
/// | output `points_W` | Eigen::Matrix3Xd | the points |
/// | output `sensor_W` | vector of size 3 | the sensor's position (robot + sensor height) |
/// | output `probabilities` | Eigen::MatrixXd | 2 x points: plants, water |
class ScenarioSensor final : public systems::LeafSystem {
 public:
  explicit ScenarioSensor(TraverseScenario scenario);

  const systems::InputPort& get_robot_input_port() const { return get_input_port(0); }

 private:
  void Sample(const Eigen::Vector2d& robot, Eigen::Matrix3Xd* points, Eigen::MatrixXd* probabilities) const;

  TraverseScenario scenario_;
};

}  // namespace cairn::planning
