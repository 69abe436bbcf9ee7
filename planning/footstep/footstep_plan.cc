#include <cairn/common/number_text.h>
#include <cairn/planning/footstep/footstep_plan.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace cairn::planning {

Stance FootstepPlan::StanceAfter(int k) const {
  if (k < -1 || k >= static_cast<int>(steps.size())) {
    throw std::out_of_range("FootstepPlan::StanceAfter: step " + cairn::FormatShort(k) + " is outside [-1, " +
                            cairn::FormatShort(static_cast<int>(steps.size()) - 1) + "]");
  }
  Stance stance = start;
  for (int j = 0; j <= k; ++j) {
    (steps[j].side == FootSide::kLeft ? stance.left : stance.right) = steps[j].pose;
  }
  return stance;
}

void FootstepPlan::UpdateTotals() {
  cost = energy = duration = distance = max_rcof = 0.0;
  min_friction_margin = steps.empty() ? 0.0 : std::numeric_limits<double>::infinity();
  Stance stance = start;
  for (const PlannedStep& step : steps) {
    const double mx0 = 0.5 * (stance.left.x + stance.right.x), my0 = 0.5 * (stance.left.y + stance.right.y);
    (step.side == FootSide::kLeft ? stance.left : stance.right) = step.pose;
    const double mx1 = 0.5 * (stance.left.x + stance.right.x), my1 = 0.5 * (stance.left.y + stance.right.y);
    distance += std::hypot(mx1 - mx0, my1 - my0);
    cost += step.transition.cost;
    energy += step.transition.com_work + step.transition.heat;
    duration += step.transition.duration;
    max_rcof = std::max(max_rcof, step.transition.rcof);
    min_friction_margin = std::min(min_friction_margin, step.mu_allowed - step.transition.rcof);
  }
}

}  // namespace cairn::planning
