#include "cairn/perception/occupancy/wta_range_sensor_model.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "cairn/common/cairn_assert.h"
#include "cairn/perception/occupancy/internal/ray_integration.h"

namespace cairn::perception {

WtaRangeSensorModel::WtaRangeSensorModel(const Options& options) : options_(options) {
  if (!(options.sigma_disparity > 0.0)) {
    throw std::invalid_argument("WtaRangeSensorModel: sigma_disparity " + std::to_string(options.sigma_disparity) +
                                " must be positive (about 1 px is typical)");
  }
  if (!(options.min_peak_ratio >= 0.0)) {
    throw std::invalid_argument("WtaRangeSensorModel: min_peak_ratio " + std::to_string(options.min_peak_ratio) +
                                " must be >= 0 (0 disables peak-ratio filtering; 1.4-1.6 are common)");
  }
  if (!(options.min_probability > 0.0 && options.min_probability < 0.5 && options.max_probability > 0.5 &&
        options.max_probability < 1.0)) {
    throw std::invalid_argument("WtaRangeSensorModel: probability limits must satisfy 0 < min < 0.5 < max < 1");
  }
}

void WtaRangeSensorModel::Integrate(const WtaResult& wta, int min_disparity, int max_disparity,
                                    const StereoCalibration& calibration, const Eigen::Isometry3d& X_WC,
                                    OccupancyGrid* grid) const {
  CAIRN_CHECK(grid != nullptr);
  calibration.Validate();
  if (wta.disparity.empty()) {
    throw std::invalid_argument("WtaRangeSensorModel: the WTA result is empty; run ComputeWinnerTakeAll() first");
  }
  if (min_disparity < 1 || max_disparity < min_disparity) {
    throw std::invalid_argument("WtaRangeSensorModel: disparity range [" + std::to_string(min_disparity) + ", " +
                                std::to_string(max_disparity) + "] must start at 1 or more and not be inverted");
  }
  // The range sizes per-row scratch of the update; a disparity as wide as the image has no match anyway.
  if (max_disparity >= wta.disparity.cols) {
    throw std::invalid_argument("WtaRangeSensorModel: max disparity " + std::to_string(max_disparity) +
                                " is not below the image width " + std::to_string(wta.disparity.cols) +
                                "; pass the disparity range the matcher searched");
  }
  const int num_disp = max_disparity - min_disparity + 1;
  const double inverse_two_var = 1.0 / (2.0 * options_.sigma_disparity * options_.sigma_disparity);
  const double band = 8.0 * options_.sigma_disparity;
  internal::IntegrateRays(
      wta.disparity.rows, wta.disparity.cols, min_disparity, num_disp, calibration, X_WC,
      {options_.min_probability, options_.max_probability, options_.min_visibility, options_.num_threads},
      [&](int y, int x, float* c) {
        const float d = wta.disparity.at<float>(y, x);
        if (!std::isfinite(d)) return false;
        if (wta.peak_ratio.at<float>(y, x) < options_.min_peak_ratio) return false;
        if (options_.require_lr_consistency && wta.lr_consistent.at<uint8_t>(y, x) == 0) return false;
        // Beyond 8 sigma the Gaussian is below 1e-14 of its peak, under float resolution of the ray's unit
        // total: those samples are exactly 0 in effect, so only the band around d is evaluated.
        const double centre = d - min_disparity;
        const int k_begin = std::max(0, static_cast<int>(std::floor(centre - band)));
        const int k_end = std::min(num_disp, static_cast<int>(std::ceil(centre + band)) + 1);
        std::fill(c, c + num_disp, 0.0f);
        for (int k = k_begin; k < k_end; ++k) {
          const double r = k - centre;
          c[k] = static_cast<float>(std::exp(-r * r * inverse_two_var));
        }
        return true;
      },
      grid);
}

}  // namespace cairn::perception
