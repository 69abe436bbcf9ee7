#include <cairn/planning/locomotion/oracle_held_out_error.h>

#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>

#include <cairn/common/number_text.h>

namespace cairn::planning {
namespace {

// A uniform double in [0, 1) from the generator's top 53 bits: the same on every standard library, unlike
// std::uniform_real_distribution.
double Unit(std::mt19937_64& rng) { return static_cast<double>(rng() >> 11) * 0x1.0p-53; }

double Between(std::mt19937_64& rng, const std::vector<double>& axis) {
  return axis.front() + (axis.back() - axis.front()) * Unit(rng);
}

}  // namespace

OracleHeldOutError MeasureOracleHeldOutError(const TransitionOracle& oracle, const TransitionSource& source,
                                             const WalkingModel& model, const OracleHeldOutOptions& options) {
  if (options.num_samples < 1 || options.num_samples > 100000) {
    throw std::invalid_argument("MeasureOracleHeldOutError: num_samples " + FormatShort(options.num_samples) +
                                " is outside [1, 100000]");
  }
  if (source.Describe() != oracle.source()) {
    throw std::invalid_argument("MeasureOracleHeldOutError: the table was built from source '" + oracle.source() +
                                "', not '" + source.Describe() + "'; compare a table with its own source");
  }
  if (model.content_hash() != oracle.model_hash()) {
    throw std::invalid_argument("MeasureOracleHeldOutError: the table was built for another walking model than '" +
                                model.name() + "'; pass the oracle's model");
  }
  const OracleGrid& grid = oracle.grid();
  std::mt19937_64 rng(options.seed);
  OracleHeldOutError result;
  const auto total = static_cast<std::size_t>(options.num_samples);
  result.samples.reserve(total);
  for (std::size_t i = 0; i < total; ++i) {
    HeldOutSample s;
    s.d = {Between(rng, grid.dx), Between(rng, grid.dy), Between(rng, grid.dz), Between(rng, grid.dtheta)};
    s.mu = grid.mu[static_cast<std::size_t>(Unit(rng) * static_cast<double>(grid.mu.size()))];
    s.predicted = oracle.Evaluate(s.d, s.mu);
    s.measured = source.CellEntries(model, oracle.objective(), s.d, {s.mu}).front();
    result.samples.push_back(s);
    if (options.progress) options.progress(i + 1, total);
  }

  double sum_measured = 0.0, sum_predicted = 0.0, sum_absolute = 0.0, sum_relative = 0.0;
  for (const HeldOutSample& s : result.samples) {
    if (s.predicted.feasible && s.measured.feasible) {
      ++result.both_feasible;
      sum_measured += s.measured.cost;
      sum_predicted += s.predicted.cost;
      sum_absolute += std::abs(s.predicted.cost - s.measured.cost);
      sum_relative += std::abs(s.predicted.cost - s.measured.cost) / std::abs(s.measured.cost);
    } else if (s.predicted.feasible) {
      ++result.only_predicted;
    } else if (s.measured.feasible) {
      ++result.only_measured;
    } else {
      ++result.neither;
    }
  }
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const int n = result.both_feasible;
  result.mean_absolute_error = n > 0 ? sum_absolute / n : nan;
  result.mean_relative_error = n > 0 ? sum_relative / n : nan;
  result.smse = nan;
  result.correlation = nan;
  if (n < 2) return result;
  const double mean_measured = sum_measured / n, mean_predicted = sum_predicted / n;
  double squared_error = 0.0, var_measured = 0.0, var_predicted = 0.0, covariance = 0.0;
  for (const HeldOutSample& s : result.samples) {
    if (!(s.predicted.feasible && s.measured.feasible)) continue;
    const double e = s.predicted.cost - s.measured.cost;
    squared_error += e * e;
    var_measured += (s.measured.cost - mean_measured) * (s.measured.cost - mean_measured);
    var_predicted += (s.predicted.cost - mean_predicted) * (s.predicted.cost - mean_predicted);
    covariance += (s.measured.cost - mean_measured) * (s.predicted.cost - mean_predicted);
  }
  if (var_measured > 0.0) result.smse = squared_error / var_measured;
  if (var_measured > 0.0 && var_predicted > 0.0) result.correlation = covariance / std::sqrt(var_measured * var_predicted);
  return result;
}

}  // namespace cairn::planning
