#include "cairn/perception/terrain/collapsibility_estimator.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "cairn/common/number_text.h"

namespace cairn::perception {

CollapsibilityEstimator::CollapsibilityEstimator(const Options& options) : options_(options) {
  if (!(options.hard_force > 0.0) || !std::isfinite(options.hard_force)) {
    throw std::invalid_argument("CollapsibilityEstimator: hard_force " + FormatShort(options.hard_force) +
                                " N must be positive and finite (seed 001: 100)");
  }
  if (options.window < 1 || options.window > kMaxWindow) {
    throw std::invalid_argument("CollapsibilityEstimator: window " + FormatShort(options.window) +
                                " samples must be in [1, " + FormatShort(kMaxWindow) + "]");
  }
  ring_.assign(options.window, 0.0);
}

double CollapsibilityEstimator::FromForce(double force, double hard_force) {
  return std::min(std::max(hard_force - force, 0.0) / hard_force, 1.0);
}

void CollapsibilityEstimator::AddSample(double force) {
  if (!std::isfinite(force)) {
    throw std::invalid_argument("CollapsibilityEstimator: force sample " + FormatShort(force) + " N is not finite");
  }
  ring_[next_] = force;
  next_ = (next_ + 1) % options_.window;
  count_ = std::min(count_ + 1, options_.window);
}

void CollapsibilityEstimator::Reset() {
  next_ = 0;
  count_ = 0;
}

double CollapsibilityEstimator::AverageForce() const {
  if (count_ == 0) throw std::logic_error("CollapsibilityEstimator: no force sample yet (call AddSample first)");
  double sum = 0.0;
  for (int k = 0; k < count_; ++k) sum += ring_[(next_ - 1 - k + options_.window) % options_.window];
  return sum / count_;
}

double CollapsibilityEstimator::Collapsibility() const { return FromForce(AverageForce(), options_.hard_force); }

}  // namespace cairn::perception
