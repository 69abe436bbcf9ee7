#include <cairn/planning/locomotion/transition_source.h>

#include <cmath>
#include <cstddef>
#include <stdexcept>

#include <cairn/common/number_text.h>

namespace cairn::planning {

std::vector<TransitionCost> TransitionSource::CellEntries(const WalkingModel& model, WalkingObjective objective,
                                                          const StepDisplacement& d,
                                                          const std::vector<double>& mu) const {
  if (mu.empty()) throw std::invalid_argument("TransitionSource::CellEntries: give at least one friction limit");
  for (std::size_t k = 0; k < mu.size(); ++k) {
    if (!(std::isfinite(mu[k]) && mu[k] > 0.0) || (k > 0 && !(mu[k] > mu[k - 1]))) {
      throw std::invalid_argument("TransitionSource::CellEntries: friction limit " + FormatShort(mu[k]) +
                                  " must be finite, > 0 and larger than the one before it");
    }
  }
  if (!(std::isfinite(d.dx) && std::isfinite(d.dy) && std::isfinite(d.dz) && std::isfinite(d.dtheta))) {
    throw std::invalid_argument("TransitionSource::CellEntries: the displacement is not finite");
  }
  std::vector<TransitionCost> entries = DoCellEntries(model, objective, d, mu);
  if (entries.size() != mu.size()) {
    throw std::logic_error("TransitionSource '" + name() + "' gave " + FormatShort(entries.size()) + " entries for " +
                           FormatShort(mu.size()) + " friction limits");
  }
  return entries;
}

}  // namespace cairn::planning
