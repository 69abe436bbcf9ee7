#pragma once

/// @file
/// ElevationFusion: fuses point clouds into a grid map's elevation layer, cell by cell with eq. (1) of seed 001.

#include <cstdint>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <opencv2/core.hpp>

#include "cairn/perception/terrain/grid_map.h"
#include "cairn/perception/terrain/range_variance_model.h"

namespace cairn::perception {

/// Fuses world-frame points into the layers "elevation" (mean height, m) and "elevation_variance" (m²) of a
/// GridMap: each point's height is a measurement of its cell with variance σ(r)² of its ray length r from the
/// sensor (RangeVarianceModel), fused by the one-dimensional Kalman update (KalmanCellUpdate). Points are fused in
/// their order in the cloud, so the result does not depend on the thread count.
///
/// The per-update path allocates nothing once the scratch buffers have grown to the largest cloud seen: the
/// points are binned to cells in parallel, then each thread fuses the points of its own band of storage rows.
class ElevationFusion {
 public:
  /// Most points one update may hold (a 4096 x 4096 depth image).
  static constexpr std::int64_t kMaxPoints = std::int64_t{1} << 24;

  /// Pinhole intrinsics of a depth camera, pixels (x right, y down, z forward).
  struct Intrinsics {
    double fx{0.0};
    double fy{0.0};
    double cx{0.0};
    double cy{0.0};
  };

  /// What the fusion does with points.
  struct Options {
    /// Sensor noise as a function of ray length.
    RangeVarianceModel noise{};
    /// Points closer to the sensor than this (m) are dropped (the sensor's minimum range).
    double min_range{0.1};
    /// Points farther than this (m) are dropped (beyond it the quadratic model is no longer a fit).
    double max_range{10.0};
    /// Threads (0 = one per core; see ResolveThreadCount).
    int num_threads{0};
  };

  /// Counts of the last update.
  struct Stats {
    std::int64_t points{0};
    std::int64_t fused{0};
    std::int64_t outside_map{0};
    std::int64_t rejected{0};  ///< non-finite or out of [min_range, max_range]
  };

  /// Throws std::invalid_argument for a bad noise model, a non-positive or inverted range window, or a thread
  /// count ResolveThreadCount refuses.
  explicit ElevationFusion(const Options& options);
  ElevationFusion() : ElevationFusion(Options{}) {}

  const Options& options() const { return options_; }

  /// Adds the layers "elevation" and "elevation_variance" to `map` if it lacks them.
  static void AddLayers(GridMap* map);

  /// Fuses the points (3 x N, world frame) seen from `sensor_W` into `map` (which needs the layers of AddLayers).
  /// Points outside the map, non-finite or out of the range window are skipped and counted. Throws
  /// std::invalid_argument for more than kMaxPoints points, a non-finite sensor position, or a missing layer.
  const Stats& Integrate(const Eigen::Matrix3Xd& points_W, const Eigen::Vector3d& sensor_W, GridMap* map);

  /// Fuses a depth image (CV_32FC1 metres along the optical axis; 0 or NaN = no return) taken with `intrinsics`
  /// from camera pose X_WC. Throws std::invalid_argument for an empty image or another type, more than kMaxPoints
  /// pixels, non-positive or non-finite focal lengths, or a non-finite pose.
  const Stats& IntegrateDepth(const cv::Mat& depth, const Intrinsics& intrinsics, const Eigen::Isometry3d& X_WC,
                              GridMap* map);

  /// Converts a depth image into world points (3 x pixels, NaN columns for pixels without return), with the same
  /// checks as IntegrateDepth. `points_W` is resized only when its size differs.
  static void DepthToPoints(const cv::Mat& depth, const Intrinsics& intrinsics, const Eigen::Isometry3d& X_WC,
                            Eigen::Matrix3Xd* points_W);

  const Stats& last_stats() const { return stats_; }

 private:
  Options options_;
  int threads_{1};
  Stats stats_;
  std::vector<int> cell_of_point_;   // storage index, -1 outside the map, -2 rejected
  std::vector<double> variance_;     // measurement variance per point
  std::vector<std::int64_t> band_counts_;
  Eigen::Matrix3Xd depth_points_;
};

}  // namespace cairn::perception
