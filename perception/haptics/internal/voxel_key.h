#pragma once

/// @file
/// Voxel keys shared by the haptics reductions, background subtraction and the simulation's checks.

#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>

#include <Eigen/Core>

#include "cairn/common/number_text.h"
#include "cairn/perception/haptics/point_cloud_reduction.h"

namespace cairn::perception::internal {

/// Throws std::invalid_argument unless `size` is positive and finite; `what` names the parameter.
inline void CheckPositiveLength(double size, const char* what) {
  if (!(size > 0.0) || !std::isfinite(size)) {
    throw std::invalid_argument(std::string(what) + " is " + FormatShort(size) +
                                " m; it must be a positive, finite length in metres");
  }
}

/// Throws std::invalid_argument when the cloud has more than kMaxHapticCloudPoints points.
inline void CheckCloudSize(const Eigen::Matrix3Xd& points, const char* what) {
  if (points.cols() > kMaxHapticCloudPoints) {
    throw std::invalid_argument(std::string(what) + " has " + FormatShort(static_cast<long long>(points.cols())) +
                                " points; at most " + FormatShort(static_cast<long long>(kMaxHapticCloudPoints)) +
                                " are accepted (down-sample the cloud first)");
  }
}

/// The integer cell of `p` for cells of side `size`, checked against kMaxVoxelIndex; `column` names the point.
inline Eigen::Vector3i CellOf(const Eigen::Vector3d& p, double size, Eigen::Index column) {
  Eigen::Vector3i cell;
  for (int a = 0; a < 3; ++a) {
    const double scaled = std::floor(p[a] / size);
    if (!std::isfinite(p[a]) || !(std::abs(scaled) < static_cast<double>(kMaxVoxelIndex))) {
      throw std::invalid_argument("point " + FormatShort(static_cast<long long>(column)) + " (" + FormatShort(p.x()) +
                                  ", " + FormatShort(p.y()) + ", " + FormatShort(p.z()) +
                                  ") is not finite or lies more than 2^20 cells of " + FormatShort(size) +
                                  " m from the origin; remove it or use a larger cell");
    }
    cell[a] = static_cast<int>(scaled);
  }
  return cell;
}

/// A 64-bit key of a cell whose indices lie within ±kMaxVoxelIndex.
inline std::uint64_t KeyOf(const Eigen::Vector3i& cell) {
  constexpr std::uint64_t kMask = (std::uint64_t{1} << 21) - 1;
  const auto part = [](int v) { return static_cast<std::uint64_t>(static_cast<std::int64_t>(v) + kMaxVoxelIndex) & kMask; };
  return part(cell.x()) | (part(cell.y()) << 21) | (part(cell.z()) << 42);
}

}  // namespace cairn::perception::internal
