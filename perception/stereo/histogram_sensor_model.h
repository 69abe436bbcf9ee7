#pragma once

/// @file
/// The histogram sensor model (HSM, thesis section 4.3.3, eq. 4.12).

#include <cstddef>
#include <limits>
#include <vector>

namespace cairn::perception {

/// An immutable histogram of window costs observed at the true (or a trusted) disparity, used as the likelihood
/// p(E_d | d) proportional to hist(E_d) (thesis eq. 4.12). Bins start at cost 0 and have Scott's normal-reference
/// width 3.5 sigma / N^(1/3), sigma being the samples' standard deviation.
///
/// Empty bins and costs beyond the last bin get a small pseudo-count instead of zero, so that a pixel whose
/// every cost falls in empty bins gets a flat confidence rather than an undefined one, and log-space arithmetic
/// never sees log(0).
class HistogramSensorModel {
 public:
  /// Trains a histogram from cost samples (finite, non-negative). `pseudo_count` is added to every bin (and used
  /// for costs beyond the last bin). Throws std::invalid_argument if fewer than two finite samples are given, if a
  /// sample is negative, if the samples have zero spread (Scott's rule needs a standard deviation), or if
  /// pseudo_count is not positive.
  static HistogramSensorModel FromSamples(const std::vector<float>& samples, double pseudo_count = 1.0);

  /// log of the density p(E = cost) up to a constant; +infinity costs give -infinity.
  double LogDensity(float cost) const {
    if (!(cost < kMaxCost)) return -std::numeric_limits<double>::infinity();
    const double bin = static_cast<double>(cost) * inverse_bin_width_;
    if (bin < 0.0) return log_density_.front();
    const auto index = static_cast<std::size_t>(bin);
    return index < log_density_.size() ? log_density_[index] : log_density_outside_;
  }

  /// Width of every bin (cost units).
  double bin_width() const { return bin_width_; }
  /// Number of samples per bin (without the pseudo-count).
  const std::vector<double>& counts() const { return counts_; }
  /// Number of samples the histogram was trained on.
  std::size_t num_samples() const { return num_samples_; }

 private:
  static constexpr float kMaxCost = 3.0e38f;
  HistogramSensorModel() = default;

  double bin_width_{1.0};
  double inverse_bin_width_{1.0};
  std::vector<double> counts_;
  std::vector<double> log_density_;
  double log_density_outside_{0.0};
  std::size_t num_samples_{0};
};

}  // namespace cairn::perception
