#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

#include <cairn/planning/locomotion/step_cost_model.h>
#include <cairn/planning/locomotion/transition_oracle.h>
#include <cairn/planning/locomotion/transition_source.h>
#include <cairn/planning/locomotion/walking_model.h>

namespace cairn::planning {

/// One held-out step: the table's interpolated answer against its source's own at that step.
struct HeldOutSample {
  StepDisplacement d;
  double mu{0.0};
  TransitionCost predicted;  ///< TransitionOracle::Evaluate
  TransitionCost measured;   ///< TransitionSource::CellEntries at (d, mu)
};

/// How well an oracle table predicts its source between its grid values (thesis 2.3.3 reports the standardised
/// mean squared error, SMSE, of its fitted models on held-out gaits). Costs are compared where both say feasible;
/// where they disagree on feasibility is counted apart.
struct OracleHeldOutError {
  std::vector<HeldOutSample> samples;
  int both_feasible{0};
  int only_predicted{0};  ///< the table says feasible, the source does not
  int only_measured{0};   ///< the source walks it, the table says infeasible
  int neither{0};
  /// Over the samples feasible for both: mean squared error / variance of the measured cost (NaN with fewer than
  /// two such samples or no variance).
  double smse{0.0};
  double mean_absolute_error{0.0};  ///< in the objective's unit
  double mean_relative_error{0.0};  ///< |predicted - measured| / measured
  double correlation{0.0};          ///< Pearson's, predicted against measured cost (NaN as smse)
};

/// Options of MeasureOracleHeldOutError.
struct OracleHeldOutOptions {
  /// Held-out steps; in [1, 100000].
  int num_samples{20};
  /// Seeds the steps: each axis uniform between the grid's first and last value, mu one of the grid's values
  /// (the table floors mu to its grid, so the source is asked at the value the table answers for).
  std::uint64_t seed{1};
  /// Called after each sample as (done, total).
  std::function<void(std::size_t done, std::size_t total)> progress;
};

/// Draws held-out steps over `oracle`'s grid and compares its answers with `source`'s. The source must be the
/// one the table was built from for the comparison to mean anything: throws std::invalid_argument when its
/// Describe() line differs from oracle.source() or the model is not the oracle's (by content hash), or for options
/// out of range; throws as the source does.
OracleHeldOutError MeasureOracleHeldOutError(const TransitionOracle& oracle, const TransitionSource& source,
                                             const WalkingModel& model,
                                             const OracleHeldOutOptions& options = OracleHeldOutOptions());

}  // namespace cairn::planning
