#include <cairn/planning/locomotion/model_transition_source.h>

#include <cstddef>

namespace cairn::planning {

std::vector<TransitionCost> ModelTransitionSource::DoCellEntries(const WalkingModel& model,
                                                                 WalkingObjective objective,
                                                                 const StepDisplacement& d,
                                                                 const std::vector<double>& mu) const {
  const std::size_t num_mu = mu.size();
  std::vector<TransitionCost> entries(num_mu);
  // From the largest mu down. An optimum that already meets a smaller mu is optimal there too; otherwise SLSQP
  // follows the optimum from the previous mu, with the global search as the fallback. A step that is infeasible
  // at some mu is infeasible at every smaller one (the constraint only tightens).
  for (std::size_t k = num_mu; k-- > 0;) {
    if (k + 1 == num_mu) {
      entries[k] = OptimizeTransition(model, d, mu[k], objective, nullptr, optimizer_);
    } else if (!entries[k + 1].feasible) {
      entries[k] = TransitionCost{};
    } else if (entries[k + 1].rcof <= mu[k]) {
      entries[k] = entries[k + 1];
    } else {
      entries[k] = OptimizeTransition(model, d, mu[k], objective, &entries[k + 1].parameters, optimizer_);
      if (!entries[k].feasible) entries[k] = OptimizeTransition(model, d, mu[k], objective, nullptr, optimizer_);
    }
  }
  // A step feasible at a smaller mu is feasible at every larger one: keep the cost non-increasing in mu.
  for (std::size_t k = 1; k < num_mu; ++k) {
    if (entries[k - 1].feasible && (!entries[k].feasible || entries[k - 1].cost < entries[k].cost)) {
      entries[k] = entries[k - 1];
    }
  }
  return entries;
}

}  // namespace cairn::planning
