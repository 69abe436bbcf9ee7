#pragma once

#include <cairn/planning/locomotion/transition_optimizer.h>
#include <cairn/planning/locomotion/transition_source.h>

namespace cairn::planning {

/// The analytic source, "model": each entry is OptimizeTransition over the walking model's pattern generator
/// (LIPM pattern, COM work, motor heat, Psi). The friction limits are solved from the largest down (the largest with
/// DIRECT + SLSQP). A solution whose RCOF is within the next smaller limit is reused (it is optimal there too);
/// otherwise SLSQP is warm-started from it, falling back to DIRECT + SLSQP if that fails; a cell infeasible at
/// some limit is infeasible at every smaller one. A final pass keeps the cost non-increasing in mu.
class ModelTransitionSource final : public TransitionSource {
 public:
  /// The name of this source, written into oracle headers.
  static constexpr const char* kName = "model";

  explicit ModelTransitionSource(const TransitionOptimizerOptions& optimizer = TransitionOptimizerOptions())
      : optimizer_(optimizer) {}

  const TransitionOptimizerOptions& optimizer() const { return optimizer_; }

 private:
  std::string do_name() const override { return kName; }
  std::vector<TransitionCost> DoCellEntries(const WalkingModel& model, WalkingObjective objective,
                                            const StepDisplacement& d, const std::vector<double>& mu) const override;

  TransitionOptimizerOptions optimizer_;
};

}  // namespace cairn::planning
