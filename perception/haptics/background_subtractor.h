#pragma once

/// @file
/// Foreground segmentation against a reference cloud, the antenna-tip segmentation of seed 000 §3.2.

#include <cstdint>
#include <unordered_set>

#include <Eigen/Core>

namespace cairn::perception {

/// The change detection of an octree at leaf resolution (what the paper uses, via PCL's octree change detector):
/// the reference cloud marks the occupied cells of a grid of side `resolution`, and the foreground of a new cloud
/// is its points in cells the reference left empty. A flat hash set of cells gives the same leaves as an octree
/// of that resolution without the tree, which only pays off for spatial queries the method does not make.
class BackgroundSubtractor {
 public:
  /// Throws std::invalid_argument for a non-positive resolution or a reference the voxel grid refuses.
  BackgroundSubtractor(const Eigen::Matrix3Xd& reference, double resolution);

  /// The points of `points` in cells the reference does not occupy, in order.
  Eigen::Matrix3Xd Foreground(const Eigen::Matrix3Xd& points) const;

  double resolution() const { return resolution_; }
  /// Cells the reference occupies.
  std::int64_t reference_cells() const { return static_cast<std::int64_t>(cells_.size()); }

 private:
  double resolution_;
  std::unordered_set<std::uint64_t> cells_;
};

}  // namespace cairn::perception
