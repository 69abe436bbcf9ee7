#include <cairn/planning/footstep/refine_footstep_plan.h>

#include <algorithm>
#include <stdexcept>

#include <cairn/planning/locomotion/transition_optimizer.h>

namespace cairn::planning {

int RefineFootstepPlan(const WalkingModel& model, WalkingObjective objective, FootstepPlan* plan) {
  if (plan == nullptr) throw std::invalid_argument("RefineFootstepPlan: plan must not be null");
  if (!plan->found) return 0;
  int refined = 0;
  for (PlannedStep& step : plan->steps) {
    // Table parameters are convex combinations of in-bounds values; rounding may leave them 1 ulp outside.
    const StepParameters& lo = model.parameter_lower();
    const StepParameters& hi = model.parameter_upper();
    StepParameters warm_start = step.transition.parameters;
    warm_start.t_ds = std::clamp(warm_start.t_ds, lo.t_ds, hi.t_ds);
    warm_start.t_sw = std::clamp(warm_start.t_sw, lo.t_sw, hi.t_sw);
    warm_start.com_height = std::clamp(warm_start.com_height, lo.com_height, hi.com_height);
    const TransitionCost exact = OptimizeTransition(model, step.displacement, step.mu_allowed, objective, &warm_start);
    if (exact.feasible && exact.rcof <= step.mu_allowed) {
      step.transition = exact;
      ++refined;
    }
  }
  plan->UpdateTotals();
  return refined;
}

}  // namespace cairn::planning
