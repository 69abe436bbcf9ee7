#pragma once

#include <memory>
#include <vector>

#include <cairn/multibody/model.h>
#include <cairn/planning/footstep/footstep_plan.h>
#include <cairn/planning/trajectory/collision_penalty.h>
#include <cairn/planning/trajectory/trajectory_optimizer_options.h>
#include <cairn/planning/trajectory/whole_body_trajectory.h>
#include <cairn/systems/framework/leaf_system.h>

namespace cairn::planning {

/// Whole-body trajectory optimisation as a block (thesis 2.5.1b, Fig. 5.1): OptimizeWholeBodyTrajectory() on
/// the footstep plan and environment at its inputs.
///
/// | port | type | meaning |
/// |---|---|---|
/// | input `plan` | FootstepPlan | footsteps with timing (FootstepPlanner's `plan`) |
/// | input `environment` | std::vector<EnvironmentBox> | obstacle boxes (the ground is options.ground_height) |
/// | input `terrain` | TerrainMap | the ground under the plan: its cells' normals tilt the sole targets and its planes are the collision terms' ground; cells without ground (or the port left unconnected on a lone system) keep soles level over options.ground_height |
/// | output `trajectory` | WholeBodyTrajectory | waypoints q_t, contacts, COM, and the solver report |
///
/// The solve is expensive and its iterations are budgeted, not timed, so it runs in events and its result lives
/// in an abstract state that the output only copies: an unrestricted update at initialization (Simulator
/// start), on ExecuteForcedEvents, and, with a positive `period`, every period seconds (replanning). Before the
/// first solve the output is an empty trajectory whose report says "not solved yet".
class TrajectoryOptimizer final : public systems::LeafSystem {
 public:
  /// Throws std::invalid_argument for a null model, options out of range (ValidateTrajectoryOptimizerOptions)
  /// or a period that is negative or not finite.
  TrajectoryOptimizer(std::shared_ptr<const multibody::Model> model, const TrajectoryOptimizerOptions& options,
                      double period = 0.0);

  const systems::InputPort& get_plan_input_port() const { return GetInputPort("plan"); }
  const systems::InputPort& get_environment_input_port() const { return GetInputPort("environment"); }
  const systems::InputPort& get_terrain_input_port() const { return GetInputPort("terrain"); }
  const systems::OutputPort& get_trajectory_output_port() const { return GetOutputPort("trajectory"); }

  /// The options.
  const TrajectoryOptimizerOptions& options() const { return options_; }

 private:
  void Solve(const systems::Context& context, systems::State* next) const;

  std::shared_ptr<const multibody::Model> model_;
  TrajectoryOptimizerOptions options_;
  int trajectory_state_{};
};

}  // namespace cairn::planning
