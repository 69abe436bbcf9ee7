#pragma once

/// @file
/// The point-cloud reductions the haptic affordance method (seed 000) is built on: the 1 cm minimum-distance
/// down-sampling of the descriptor (§3.3), the voxel-grid centroids of interaction planning (§3.5) and of the
/// change-detection gist (§3.7), and the antenna-reach segmentation. Clouds are 3 x N matrices, one point a column.

#include <cstdint>

#include <Eigen/Core>

namespace cairn::perception {

/// Most points a haptics routine accepts in one cloud: 2^24 (a 16.7 Mpixel depth image; a Kinect frame is 0.3 M).
inline constexpr std::int64_t kMaxHapticCloudPoints = std::int64_t{1} << 24;

/// Most voxels a point may lie from the origin along any axis (|x| / voxel < 2^20): voxel keys pack three 21-bit
/// signed indices into 64 bits. At 1 cm that is ±10 km.
inline constexpr std::int64_t kMaxVoxelIndex = std::int64_t{1} << 20;

/// Greedy down-sampling in column order: a point is kept unless a kept point lies closer than `min_distance`, so
/// no two kept points are within `min_distance` of each other (the paper's "no point within a 1 cm radius of
/// another"). Kept points keep their order. Throws std::invalid_argument for a non-positive or non-finite
/// distance, more than kMaxHapticCloudPoints points, a non-finite point, or a point beyond kMaxVoxelIndex cells.
Eigen::Matrix3Xd DownsampleByMinDistance(const Eigen::Matrix3Xd& points, double min_distance);

/// The centroids of the occupied cells of a regular grid of cubic voxels of side `voxel` aligned with the
/// origin, in the order each cell is first met in `points` (so the result does not depend on hashing). Throws as
/// DownsampleByMinDistance.
Eigen::Matrix3Xd VoxelGridCentroids(const Eigen::Matrix3Xd& points, double voxel);

/// The number of occupied voxels (the size of VoxelGridCentroids without computing the centroids).
std::int64_t CountOccupiedVoxels(const Eigen::Matrix3Xd& points, double voxel);

/// The points within `radius` of `center` (the antenna's reach, §3.3), in order. Throws std::invalid_argument for
/// a negative or non-finite radius, a non-finite centre, or more than kMaxHapticCloudPoints points.
Eigen::Matrix3Xd KeepWithinReach(const Eigen::Matrix3Xd& points, const Eigen::Vector3d& center, double radius);

}  // namespace cairn::perception
