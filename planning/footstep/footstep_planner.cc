#include <cairn/planning/footstep/footstep_planner.h>

#include <cmath>
#include <stdexcept>
#include <utility>

#include <cairn/common/number_text.h>

#include <cairn/planning/footstep/plan_footsteps.h>
#include <cairn/planning/footstep/refine_footstep_plan.h>
#include <cairn/systems/framework/state.h>

namespace cairn::planning {

using systems::AbstractValue;
using systems::Context;
using systems::Value;

namespace {
FootstepPlan NotPlannedYet() {
  FootstepPlan plan;
  plan.reason = "not planned yet: the search runs at initialization, on forced events or periodically";
  return plan;
}
}  // namespace

FootstepPlanner::FootstepPlanner(std::shared_ptr<const StepCostModel> cost_model, const BipedGeometry& geometry,
                                 const FootstepPlannerOptions& options,
                                 std::shared_ptr<const WalkingModel> refine_model, WalkingObjective objective,
                                 double period)
    : cost_model_(std::move(cost_model)),
      geometry_(geometry),
      options_(options),
      refine_model_(std::move(refine_model)),
      objective_(objective) {
  if (cost_model_ == nullptr) {
    throw std::invalid_argument("FootstepPlanner: the step cost model is null; pass e.g. a TransitionOracle");
  }
  if (!(period >= 0.0) || !std::isfinite(period)) {
    throw std::invalid_argument("FootstepPlanner: period " + FormatShort(period) +
                                " s must be finite and >= 0 (0: plan at initialization and on forced events only)");
  }
  DeclareAbstractInputPort("terrain",
                           Value<TerrainMap>(TerrainMap(Eigen::Vector2d::Zero(), 1, 1, options.lattice_resolution)));
  DeclareAbstractInputPort("start", Value<Stance>());
  DeclareAbstractInputPort("goal", Value<StanceGoal>());
  plan_state_ = DeclareAbstractState(Value<FootstepPlan>(NotPlannedYet()));
  const int state = plan_state_;
  DeclareAbstractOutputPort(
      "plan", Value<FootstepPlan>(NotPlannedYet()),
      [state](const Context& c, AbstractValue* v) { v->SetFrom(c.get_abstract_state_value(state)); },
      {abstract_state_ticket(state)});
  DeclareInitializationUnrestrictedUpdateEvent(&FootstepPlanner::Plan);
  DeclareForcedUnrestrictedUpdateEvent(&FootstepPlanner::Plan);
  if (period > 0.0) DeclarePeriodicUnrestrictedUpdateEvent(period, period, &FootstepPlanner::Plan);
}

void FootstepPlanner::Plan(const Context& context, systems::State* next) const {
  FootstepPlan& plan = next->get_mutable_abstract_state<FootstepPlan>(plan_state_);
  plan = PlanFootsteps(get_terrain_input_port().Eval<TerrainMap>(context), get_start_input_port().Eval<Stance>(context),
                       get_goal_input_port().Eval<StanceGoal>(context), *cost_model_, geometry_, options_);
  if (refine_model_ != nullptr) RefineFootstepPlan(*refine_model_, objective_, &plan);
}

}  // namespace cairn::planning
