#include "cairn/perception/haptics/point_cloud_reduction.h"

#include <cmath>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <vector>

#include "cairn/common/number_text.h"
#include "cairn/perception/haptics/internal/voxel_key.h"

namespace cairn::perception {

Eigen::Matrix3Xd DownsampleByMinDistance(const Eigen::Matrix3Xd& points, double min_distance) {
  internal::CheckPositiveLength(min_distance, "the down-sampling distance");
  internal::CheckCloudSize(points, "the cloud to down-sample");
  // Cells of side min_distance: any kept point closer than min_distance lies in one of the 27 cells around.
  std::unordered_map<std::uint64_t, std::vector<Eigen::Index>> cells;
  cells.reserve(static_cast<std::size_t>(points.cols()));
  std::vector<Eigen::Index> kept;
  kept.reserve(static_cast<std::size_t>(points.cols()));
  const double limit2 = min_distance * min_distance;
  for (Eigen::Index i = 0; i < points.cols(); ++i) {
    const Eigen::Vector3d p = points.col(i);
    const Eigen::Vector3i cell = internal::CellOf(p, min_distance, i);
    bool near = false;
    for (int dz = -1; dz <= 1 && !near; ++dz) {
      for (int dy = -1; dy <= 1 && !near; ++dy) {
        for (int dx = -1; dx <= 1 && !near; ++dx) {
          const auto found = cells.find(internal::KeyOf(cell + Eigen::Vector3i(dx, dy, dz)));
          if (found == cells.end()) continue;
          for (const Eigen::Index j : found->second) {
            if ((points.col(j) - p).squaredNorm() < limit2) {
              near = true;
              break;
            }
          }
        }
      }
    }
    if (near) continue;
    cells[internal::KeyOf(cell)].push_back(i);
    kept.push_back(i);
  }
  Eigen::Matrix3Xd result(3, static_cast<Eigen::Index>(kept.size()));
  for (std::size_t k = 0; k < kept.size(); ++k) result.col(static_cast<Eigen::Index>(k)) = points.col(kept[k]);
  return result;
}

Eigen::Matrix3Xd VoxelGridCentroids(const Eigen::Matrix3Xd& points, double voxel) {
  internal::CheckPositiveLength(voxel, "the voxel size");
  internal::CheckCloudSize(points, "the cloud to voxelise");
  std::unordered_map<std::uint64_t, std::size_t> slot_of;
  slot_of.reserve(static_cast<std::size_t>(points.cols()));
  std::vector<Eigen::Vector3d> sums;
  std::vector<double> counts;
  for (Eigen::Index i = 0; i < points.cols(); ++i) {
    const Eigen::Vector3d p = points.col(i);
    const auto [it, inserted] = slot_of.emplace(internal::KeyOf(internal::CellOf(p, voxel, i)), sums.size());
    if (inserted) {
      sums.push_back(p);
      counts.push_back(1.0);
    } else {
      sums[it->second] += p;
      counts[it->second] += 1.0;
    }
  }
  Eigen::Matrix3Xd result(3, static_cast<Eigen::Index>(sums.size()));
  for (std::size_t k = 0; k < sums.size(); ++k) result.col(static_cast<Eigen::Index>(k)) = sums[k] / counts[k];
  return result;
}

std::int64_t CountOccupiedVoxels(const Eigen::Matrix3Xd& points, double voxel) {
  internal::CheckPositiveLength(voxel, "the voxel size");
  internal::CheckCloudSize(points, "the cloud to voxelise");
  std::unordered_map<std::uint64_t, char> seen;
  seen.reserve(static_cast<std::size_t>(points.cols()));
  for (Eigen::Index i = 0; i < points.cols(); ++i) {
    seen.emplace(internal::KeyOf(internal::CellOf(points.col(i), voxel, i)), 0);
  }
  return static_cast<std::int64_t>(seen.size());
}

Eigen::Matrix3Xd KeepWithinReach(const Eigen::Matrix3Xd& points, const Eigen::Vector3d& center, double radius) {
  if (!(radius >= 0.0) || !std::isfinite(radius)) {
    throw std::invalid_argument("the reach radius is " + FormatShort(radius) +
                                " m; it must be a non-negative, finite length in metres");
  }
  if (!center.allFinite()) {
    throw std::invalid_argument("the reach centre (" + FormatShort(center.x()) + ", " + FormatShort(center.y()) +
                                ", " + FormatShort(center.z()) + ") is not finite");
  }
  internal::CheckCloudSize(points, "the cloud to segment");
  std::vector<Eigen::Index> kept;
  const double r2 = radius * radius;
  for (Eigen::Index i = 0; i < points.cols(); ++i) {
    // A NaN point fails the comparison and is dropped, as a depth sensor's invalid pixels should be.
    if ((points.col(i) - center).squaredNorm() <= r2) kept.push_back(i);
  }
  Eigen::Matrix3Xd result(3, static_cast<Eigen::Index>(kept.size()));
  for (std::size_t k = 0; k < kept.size(); ++k) result.col(static_cast<Eigen::Index>(k)) = points.col(kept[k]);
  return result;
}

}  // namespace cairn::perception
