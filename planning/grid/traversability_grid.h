#pragma once

/// @file
/// TraversabilityGrid: what the grid planners search — a traversability raster placed in the world.

#include <cstdint>

#include <Eigen/Core>

namespace cairn::planning {

/// A raster of traversability values t in [0, 1] (NaN = unknown), values(i, j) being the cell i along world x and
/// j along world y from the grid's minimum corner, with square cells of side `resolution`. Planning keeps its
/// own plain type so that it depends on no perception map; perception's GridMap layers convert to it.
struct TraversabilityGrid {
  /// Most cells a grid may hold (2^24).
  static constexpr std::int64_t kMaxCells = std::int64_t{1} << 24;

  Eigen::MatrixXd values;
  double resolution{0.05};
  Eigen::Vector2d min_corner{Eigen::Vector2d::Zero()};

  int rows() const { return static_cast<int>(values.rows()); }
  int cols() const { return static_cast<int>(values.cols()); }
  bool Contains(const Eigen::Vector2i& cell) const {
    return cell.x() >= 0 && cell.y() >= 0 && cell.x() < rows() && cell.y() < cols();
  }
  /// The cell containing p_W, or (-1, -1) outside.
  Eigen::Vector2i CellOf(const Eigen::Vector2d& p_W) const;
  /// The world position of a cell's centre.
  Eigen::Vector2d CellCenter(const Eigen::Vector2i& cell) const {
    return min_corner + (cell.cast<double>() + Eigen::Vector2d::Constant(0.5)) * resolution;
  }
  /// Throws std::invalid_argument for an empty grid, more than kMaxCells cells, a non-positive or non-finite
  /// resolution, a non-finite corner, or a value outside [0, 1] that is not NaN (naming the cell).
  void Validate() const;
};

}  // namespace cairn::planning
