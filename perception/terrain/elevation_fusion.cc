#include "cairn/perception/terrain/elevation_fusion.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "cairn/common/number_text.h"
#include "cairn/common/parallel_for.h"
#include "cairn/perception/terrain/internal/parallel_bands.h"
#include "cairn/perception/terrain/kalman_cell_update.h"

namespace cairn::perception {

namespace {

// Named once: a temporary std::string of this length would be a heap allocation on every update.
const std::string& VarianceLayerName() {
  static const std::string name = "elevation_variance";
  return name;
}

}  // namespace

ElevationFusion::ElevationFusion(const Options& options) : options_(options) {
  options.noise.Validate();
  if (!(options.min_range >= 0.0) || !std::isfinite(options.min_range) || !(options.max_range > options.min_range) ||
      !std::isfinite(options.max_range)) {
    throw std::invalid_argument("ElevationFusion: range window [" + FormatShort(options.min_range) + ", " +
                                FormatShort(options.max_range) +
                                "] m must be finite with 0 <= min_range < max_range (D435: [0.1, 10])");
  }
  threads_ = ResolveThreadCount(options.num_threads);
}

void ElevationFusion::AddLayers(GridMap* map) {
  if (!map->HasLayer("elevation")) map->AddLayer("elevation");
  if (!map->HasLayer("elevation_variance")) map->AddLayer("elevation_variance");
}

const ElevationFusion::Stats& ElevationFusion::Integrate(const Eigen::Matrix3Xd& points_W,
                                                         const Eigen::Vector3d& sensor_W, GridMap* map) {
  if (points_W.cols() > kMaxPoints) {
    throw std::invalid_argument("ElevationFusion: " + FormatShort(static_cast<long long>(points_W.cols())) +
                                " points exceed the limit of " + FormatShort(static_cast<long long>(kMaxPoints)) +
                                " per update (down-sample the cloud)");
  }
  if (!sensor_W.allFinite()) {
    throw std::invalid_argument("ElevationFusion: the sensor position must be finite");
  }
  const int elevation = map->LayerIndex("elevation");
  const int variance_layer = map->LayerIndex(VarianceLayerName());
  const int n = static_cast<int>(points_W.cols());
  if (static_cast<int>(cell_of_point_.size()) < n) {
    cell_of_point_.resize(n);
    variance_.resize(n);
  }
  const int bands = std::max(1, threads_);
  band_counts_.assign(static_cast<std::size_t>(bands) * 3, 0);  // capacity kept after the first call
  const double min_range = options_.min_range;
  const double max_range = options_.max_range;
  const RangeVarianceModel noise = options_.noise;
  // Pass 1: each point's cell and measurement variance.
  internal::ParallelBands(n, bands, threads_, [&](int band, int begin, int end) {
    std::int64_t outside = 0, rejected = 0, fused = 0;
    for (int k = begin; k < end; ++k) {
      const Eigen::Vector3d p = points_W.col(k);
      const double range = (p - sensor_W).norm();
      if (!std::isfinite(range) || range < min_range || range > max_range) {
        cell_of_point_[k] = -2;
        ++rejected;
        continue;
      }
      Eigen::Vector2i cell;
      if (!map->CellOf(p.head<2>(), &cell)) {
        cell_of_point_[k] = -1;
        ++outside;
        continue;
      }
      cell_of_point_[k] = map->StorageIndex(cell.x(), cell.y());
      variance_[k] = noise.Variance(range);
      ++fused;
    }
    band_counts_[3 * band] = fused;
    band_counts_[3 * band + 1] = outside;
    band_counts_[3 * band + 2] = rejected;
  });
  // Pass 2: each band owns a range of storage rows and fuses, in cloud order, the points that fall in it.
  auto& mean = map->layer_data(elevation);
  auto& var = map->layer_data(variance_layer);
  const int rows = map->size().x();
  const int columns = map->size().y();
  internal::ParallelBands(rows, bands, threads_, [&](int, int row_begin, int row_end) {
    const int lo = row_begin * columns;
    const int hi = row_end * columns;
    for (int k = 0; k < n; ++k) {
      const int s = cell_of_point_[k];
      if (s < lo || s >= hi) continue;
      KalmanCellUpdate(points_W(2, k), variance_[k], &mean[s], &var[s]);
    }
  });
  stats_ = Stats{};
  stats_.points = n;
  for (int b = 0; b < bands; ++b) {
    stats_.fused += band_counts_[3 * b];
    stats_.outside_map += band_counts_[3 * b + 1];
    stats_.rejected += band_counts_[3 * b + 2];
  }
  return stats_;
}

void ElevationFusion::DepthToPoints(const cv::Mat& depth, const Intrinsics& intrinsics, const Eigen::Isometry3d& X_WC,
                                    Eigen::Matrix3Xd* points_W) {
  if (depth.empty() || depth.type() != CV_32FC1) {
    throw std::invalid_argument("ElevationFusion: the depth image must be a non-empty CV_32FC1 image in metres");
  }
  if (static_cast<std::int64_t>(depth.rows) * depth.cols > kMaxPoints) {
    throw std::invalid_argument("ElevationFusion: a " + FormatShort(depth.cols) + " x " + FormatShort(depth.rows) +
                                " depth image exceeds the limit of " +
                                FormatShort(static_cast<long long>(kMaxPoints)) + " pixels");
  }
  if (!(intrinsics.fx > 0.0) || !(intrinsics.fy > 0.0) || !std::isfinite(intrinsics.fx) ||
      !std::isfinite(intrinsics.fy) || !std::isfinite(intrinsics.cx) || !std::isfinite(intrinsics.cy)) {
    throw std::invalid_argument("ElevationFusion: intrinsics fx = " + FormatShort(intrinsics.fx) + ", fy = " +
                                FormatShort(intrinsics.fy) + " must be positive and finite (pixels)");
  }
  if (!X_WC.matrix().allFinite()) throw std::invalid_argument("ElevationFusion: the camera pose must be finite");
  const int count = depth.rows * depth.cols;
  if (points_W->cols() != count) points_W->resize(3, count);
  const Eigen::Matrix3d R = X_WC.linear();
  const Eigen::Vector3d t = X_WC.translation();
  for (int v = 0; v < depth.rows; ++v) {
    const float* row = depth.ptr<float>(v);
    for (int u = 0; u < depth.cols; ++u) {
      const double z = row[u];
      const int k = v * depth.cols + u;
      if (!(z > 0.0) || !std::isfinite(z)) {
        points_W->col(k).setConstant(std::numeric_limits<double>::quiet_NaN());
        continue;
      }
      const Eigen::Vector3d p_C((u - intrinsics.cx) * z / intrinsics.fx, (v - intrinsics.cy) * z / intrinsics.fy, z);
      points_W->col(k) = R * p_C + t;
    }
  }
}

const ElevationFusion::Stats& ElevationFusion::IntegrateDepth(const cv::Mat& depth, const Intrinsics& intrinsics,
                                                              const Eigen::Isometry3d& X_WC, GridMap* map) {
  DepthToPoints(depth, intrinsics, X_WC, &depth_points_);
  return Integrate(depth_points_, X_WC.translation(), map);
}

}  // namespace cairn::perception
