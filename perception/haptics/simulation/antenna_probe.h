#pragma once

/// @file
/// AntennaProbe: the simulated antenna plant with its plan-following controller, as a block-diagram system.

#include <vector>

#include <Eigen/Geometry>

#include "cairn/perception/haptics/haptic_interaction_planner.h"
#include "cairn/perception/haptics/haptic_outcome.h"
#include "cairn/perception/haptics/simulation/haptic_scene_object.h"
#include "cairn/perception/haptics/simulation/simulated_antenna.h"
#include "cairn/systems/framework/leaf_system.h"

namespace cairn::perception {

/// Every `period` seconds (from `offset`), when the plan on its input selects points, maps the targets from the sensor frame to
/// the antenna's with the calibration X_CA, sweeps the antenna through them (SimulatedAntenna::Probe against the
/// objects) and holds the outcome, labelled with the descriptor the plan was made for. A plan with no point
/// (the memory was confident) leaves the last outcome in place.
///
/// | port | type | meaning |
/// |---|---|---|
/// | input `plan` | InteractionPlan | InteractionPlanner's `plan` |
/// | input `descriptor` | AffordanceDescriptor | the descriptor of the object planned for |
/// | input `X_WC` | Eigen::Isometry3d | the sensor's pose (the antenna base is at X_WC X_CA) |
/// | output `outcome` | HapticOutcome | the last interaction (sequence -1 before the first) (state) |
/// | output `interactions` | vector (2) | [interactions so far, targets touched in the last one] (state) |
class AntennaProbe final : public systems::LeafSystem {
 public:
  /// Throws std::invalid_argument for invalid antenna options, a non-positive period or a negative offset.
  AntennaProbe(const SimulatedAntenna::Options& antenna, std::vector<HapticSceneObject> objects_W,
               const Eigen::Isometry3d& X_CA, int descriptor_lines, double period, double offset = 0.0);

  const systems::InputPort& get_plan_input_port() const { return get_input_port(0); }
  const systems::InputPort& get_descriptor_input_port() const { return get_input_port(1); }
  const systems::InputPort& get_pose_input_port() const { return get_input_port(2); }
  const systems::OutputPort& get_outcome_output_port() const { return get_output_port(0); }
  const systems::OutputPort& get_interactions_output_port() const { return get_output_port(1); }

 private:
  void Probe(const systems::Context& context, systems::State* next) const;

  SimulatedAntenna antenna_;
  std::vector<HapticSceneObject> objects_W_;
  Eigen::Isometry3d X_CA_;
  int outcome_state_{};
  int count_state_{};
};

}  // namespace cairn::perception
