#pragma once

#include <memory>

#include <cairn/planning/footstep/biped_geometry.h>
#include <cairn/planning/footstep/foot_pose.h>
#include <cairn/planning/footstep/footstep_plan.h>
#include <cairn/planning/footstep/footstep_planner_options.h>
#include <cairn/planning/footstep/terrain_map.h>
#include <cairn/planning/locomotion/step_cost_model.h>
#include <cairn/planning/locomotion/walking_model.h>
#include <cairn/planning/locomotion/walking_objective.h>
#include <cairn/systems/framework/leaf_system.h>

namespace cairn::planning {

/// Energy- and friction-aware footstep planning with step timing as a block (thesis 2.4, 5.2.1): PlanFootsteps()
/// over the input terrain, then, when a walking model is given, RefineFootstepPlan().
///
/// | port | type | meaning |
/// |---|---|---|
/// | input `terrain` | TerrainMap | friction-annotated terrain (friction already Q_{1-eta}) and obstacles |
/// | input `start` | Stance | where the feet are |
/// | input `goal` | StanceGoal | where they should end |
/// | output `plan` | FootstepPlan | steps, timing, predicted energy and RCOF, or the reason there is none |
///
/// The search is expensive, so it runs in events and its result lives in an abstract state that the output only
/// copies (DESIGN.md 3.1): an unrestricted update at initialization (Simulator start), on ExecuteForcedEvents
/// (e.g. after the terrain or goal changed), and, with a positive `period`, every period seconds (replanning as
/// the robot walks and perception updates the terrain). Before the first search the output is an empty plan
/// whose reason says "not planned yet". Give the search an expansion budget (options.search.max_expansions)
/// when the plan must not depend on the machine's speed.
class FootstepPlanner final : public systems::LeafSystem {
 public:
  /// `cost_model` prices steps (typically a TransitionOracle). With `refine_model`, each plan's steps are refined
  /// on it for `objective` (which must be the objective the cost model was built for). Throws
  /// std::invalid_argument for a null cost model or a period that is negative or not finite.
  FootstepPlanner(std::shared_ptr<const StepCostModel> cost_model, const BipedGeometry& geometry,
                  const FootstepPlannerOptions& options, std::shared_ptr<const WalkingModel> refine_model = nullptr,
                  WalkingObjective objective = WalkingObjective::kComWorkPlusHeat, double period = 0.0);

  const systems::InputPort& get_terrain_input_port() const { return GetInputPort("terrain"); }
  const systems::InputPort& get_start_input_port() const { return GetInputPort("start"); }
  const systems::InputPort& get_goal_input_port() const { return GetInputPort("goal"); }
  const systems::OutputPort& get_plan_output_port() const { return GetOutputPort("plan"); }

 private:
  void Plan(const systems::Context& context, systems::State* next) const;

  std::shared_ptr<const StepCostModel> cost_model_;
  BipedGeometry geometry_;
  FootstepPlannerOptions options_;
  std::shared_ptr<const WalkingModel> refine_model_;
  WalkingObjective objective_;
  int plan_state_{-1};
};

}  // namespace cairn::planning
