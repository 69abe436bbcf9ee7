#pragma once

/// @file
/// The traditional range-sensor occupancy model on WTA stereo (thesis section 4.4.1b).

#include <Eigen/Geometry>

#include "cairn/perception/occupancy/occupancy_grid.h"
#include "cairn/perception/stereo/stereo_calibration.h"
#include "cairn/perception/stereo/winner_take_all.h"

namespace cairn::perception {

/// The winner-take-all special case of CostCurveSensorModel: each pixel keeps only its WTA disparity k and its
/// likelihood becomes p(E | O_i, V_i) proportional to exp(-(d_i - k)^2 / (2 sigma^2)) over disparity; the same
/// equations then give free space before the measured depth, a Gaussian bump around it and no information behind.
/// Optionally, pixels whose peak ratio is below a threshold are dropped (the usual WTA filtering).
class WtaRangeSensorModel {
 public:
  /// Parameters.
  struct Options {
    /// Standard deviation of the range likelihood, in disparity pixels (about the sub-pixel accuracy of WTA).
    double sigma_disparity{0.5};
    /// Pixels with peak ratio (second-best / best cost) below this are not integrated; 0 keeps every pixel.
    double min_peak_ratio{0.0};
    /// Also drop pixels that fail the left-right check.
    bool require_lr_consistency{false};
    /// Per-measurement probability limits, as CostCurveSensorModel::Options.
    double min_probability{0.12};
    /// See min_probability.
    double max_probability{0.97};
    /// Cells less visible than this are not updated, as CostCurveSensorModel::Options::min_visibility.
    double min_visibility{0.25};
    /// Threads (0 = one per core; rule: cairn::ResolveThreadCount).
    int num_threads{0};
  };

  /// Throws std::invalid_argument for a non-positive sigma, a negative peak-ratio threshold or bad limits.
  explicit WtaRangeSensorModel(const Options& options);

  /// Integrates one frame of WTA disparities over [min_disparity, max_disparity] (min_disparity >= 1). Like
  /// CostCurveSensorModel::Integrate(): the same grid for any thread count, accumulators kept by the calling thread.
  void Integrate(const WtaResult& wta, int min_disparity, int max_disparity, const StereoCalibration& calibration,
                 const Eigen::Isometry3d& X_WC, OccupancyGrid* grid) const;

  const Options& options() const { return options_; }

 private:
  Options options_;
};

}  // namespace cairn::perception
