#include <cairn/planning/footstep/footstep_planner.h>

#include <stdexcept>

#include <cairn/planning/footstep/plan_footsteps.h>
#include <cairn/planning/footstep/refine_footstep_plan.h>

namespace cairn::planning {

using systems::AbstractValue;
using systems::Context;
using systems::Value;

FootstepPlanner::FootstepPlanner(std::shared_ptr<const StepCostModel> cost_model, const BipedGeometry& geometry,
                                 const FootstepPlannerOptions& options,
                                 std::shared_ptr<const WalkingModel> refine_model, WalkingObjective objective)
    : cost_model_(std::move(cost_model)),
      geometry_(geometry),
      options_(options),
      refine_model_(std::move(refine_model)),
      objective_(objective) {
  if (cost_model_ == nullptr) {
    throw std::invalid_argument("FootstepPlanner: the step cost model is null; pass e.g. a TransitionOracle");
  }
  const auto& terrain = DeclareAbstractInputPort(
      "terrain", Value<TerrainMap>(TerrainMap(Eigen::Vector2d::Zero(), 1, 1, options.lattice_resolution)));
  const auto& start = DeclareAbstractInputPort("start", Value<Stance>());
  const auto& goal = DeclareAbstractInputPort("goal", Value<StanceGoal>());
  DeclareAbstractOutputPort(
      "plan", Value<FootstepPlan>(),
      [this](const Context& context, AbstractValue* value) { CalcPlan(context, &value->get_mutable_value<FootstepPlan>()); },
      {terrain.ticket(), start.ticket(), goal.ticket()});
}

void FootstepPlanner::CalcPlan(const Context& context, FootstepPlan* plan) const {
  *plan = PlanFootsteps(get_terrain_input_port().Eval<TerrainMap>(context), get_start_input_port().Eval<Stance>(context),
                        get_goal_input_port().Eval<StanceGoal>(context), *cost_model_, geometry_, options_);
  if (refine_model_ != nullptr) RefineFootstepPlan(*refine_model_, objective_, plan);
}

}  // namespace cairn::planning
