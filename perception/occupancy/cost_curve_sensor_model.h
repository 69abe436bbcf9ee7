#pragma once

/// @file
/// The cost-curve occupancy sensor model (thesis section 4.4.1, eqs. 4.13-4.17).

#include <Eigen/Geometry>

#include "cairn/perception/occupancy/occupancy_grid.h"
#include "cairn/perception/stereo/disparity_volume.h"
#include "cairn/perception/stereo/stereo_calibration.h"

namespace cairn::perception {

/// Updates an occupancy grid from a whole-range stereo confidence volume: every pixel's ray spreads its
/// confidence C(d) over the cells it crosses, and each cell gets P(O_i | E) = P(O_i | V_i, E) P(V_i | E) +
/// 0.5 (1 - P(V_i | E)) with the visibility recursion (eq. 4.14), the denominator recursion (eq. 4.16), a target
/// assumed present and equally likely at any disparity, and an uninformative 0.5 prior behind it. This has the
/// closed form P(O_i | E) = m_i + 0.5 (1 - T_i): m_i is the confidence mass of the disparity samples the cell stands
/// for (those whose centres it covers, or the one containing its middle when the cell is thinner than a disparity
/// step), T_i the mass at or beyond the cell.
///
/// Immutable; Integrate() may be called on many grids and frames.
class CostCurveSensorModel {
 public:
  /// Limits and threading.
  struct Options {
    /// Per-measurement probabilities are clamped to [min_probability, max_probability] before the log-odds
    /// update, so that one frame can never make a cell certain.
    double min_probability{0.12};
    /// See min_probability.
    double max_probability{0.97};
    /// Cells whose visibility P(V_i | E) (the confidence mass at or beyond them) is below this are left alone:
    /// the model gives them the prior 0.5 plus a sliver, and that sliver would pile up behind surfaces.
    double min_visibility{0.25};
    /// Threads splitting the image rows (0 = one per core; rule: cairn::ResolveThreadCount).
    int num_threads{0};
  };

  /// Throws std::invalid_argument unless 0 < min_probability < 0.5 < max_probability < 1.
  explicit CostCurveSensorModel(const Options& options);
  /// Default limits.
  CostCurveSensorModel();

  /// Integrates one frame: `confidence` is C(d) of the left image (ComputeConfidence), `X_WC` the left camera's
  /// pose in the grid's world frame. Requires min_disparity >= 1 so that every ray has a finite far end. Throws
  /// std::invalid_argument for an empty volume, a bad calibration, min_disparity < 1, more than 2^22 - 1 pixels
  /// (the per-frame ray count of the fixed-point accumulation) or probability limits within e^-60 of 0 or 1. The
  /// grid is the same, bit for bit, for any Options::num_threads. The calling thread keeps the per-frame
  /// accumulators (8 bytes per grid cell and worker thread) between calls, so that a stream of frames does not
  /// allocate them every frame; they are freed when it exits.
  void Integrate(const DisparityVolume& confidence, const StereoCalibration& calibration,
                 const Eigen::Isometry3d& X_WC, OccupancyGrid* grid) const;

  const Options& options() const { return options_; }

 private:
  Options options_;
};

}  // namespace cairn::perception
