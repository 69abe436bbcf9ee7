#include "cairn/common/number_text.h"
#include "cairn/perception/stereo/histogram_sensor_model.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace cairn::perception {

HistogramSensorModel HistogramSensorModel::FromSamples(const std::vector<float>& samples, double pseudo_count) {
  if (!(pseudo_count > 0.0)) {
    throw std::invalid_argument("HistogramSensorModel: pseudo_count " + cairn::FormatShort(pseudo_count) +
                                " must be positive (1 is Laplace smoothing)");
  }
  double sum = 0.0;
  double max_sample = 0.0;
  std::size_t n = 0;
  for (float s : samples) {
    if (!std::isfinite(s)) continue;
    if (s < 0.0f) {
      throw std::invalid_argument("HistogramSensorModel: cost sample " + cairn::FormatShort(s) +
                                  " is negative; window costs (SSD, BTSAD) are non-negative");
    }
    sum += s;
    max_sample = std::max(max_sample, static_cast<double>(s));
    ++n;
  }
  if (n < 2) {
    throw std::invalid_argument("HistogramSensorModel: got " + cairn::FormatShort(n) +
                                " finite cost samples; train on at least two (e.g. the costs at the ground-truth "
                                "disparity of a whole image)");
  }
  const double mean = sum / static_cast<double>(n);
  double squares = 0.0;
  for (float s : samples) {
    if (std::isfinite(s)) squares += (s - mean) * (s - mean);
  }
  const double sigma = std::sqrt(squares / static_cast<double>(n - 1));
  if (!(sigma > 0.0)) {
    throw std::invalid_argument("HistogramSensorModel: all " + cairn::FormatShort(n) + " cost samples equal " +
                                cairn::FormatShort(mean) + "; Scott's bin width needs spread, train on more varied costs");
  }
  HistogramSensorModel model;
  model.num_samples_ = n;
  model.bin_width_ = 3.5 * sigma / std::cbrt(static_cast<double>(n));
  model.inverse_bin_width_ = 1.0 / model.bin_width_;
  const auto bins = static_cast<std::size_t>(std::floor(max_sample * model.inverse_bin_width_)) + 1;
  model.counts_.assign(bins, 0.0);
  for (float s : samples) {
    if (!std::isfinite(s)) continue;
    const auto index = std::min(bins - 1, static_cast<std::size_t>(static_cast<double>(s) * model.inverse_bin_width_));
    model.counts_[index] += 1.0;
  }
  const double total = static_cast<double>(n) + pseudo_count * static_cast<double>(bins + 1);
  model.log_density_.resize(bins);
  for (std::size_t b = 0; b < bins; ++b) {
    model.log_density_[b] = std::log((model.counts_[b] + pseudo_count) / (total * model.bin_width_));
  }
  model.log_density_outside_ = std::log(pseudo_count / (total * model.bin_width_));
  return model;
}

}  // namespace cairn::perception
