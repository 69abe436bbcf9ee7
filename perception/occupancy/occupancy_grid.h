#pragma once

/// @file
/// A dense 3-D occupancy grid in log-odds.

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "cairn/perception/occupancy/grid_walk.h"

namespace cairn::perception {

/// A dense, axis-aligned 3-D grid of cubic cells storing the log-odds of occupancy, updated by Bayes' rule in
/// log-odds form (l += log(p / (1 - p)) for a measurement p with a 0.5 prior) and clamped so that the map stays
/// revisable (OctoMap's default clamps 0.12 / 0.97).
///
/// Dense storage (one float per cell, x fastest) rather than hashed blocks: the sensor models touch every cell
/// along hundreds of thousands of rays per frame, and a flat array makes each touch one multiply-add of an index;
/// at 5 cm over a 6.4 x 6.4 x 3.2 m volume the grid is 4 MB. perception_benchmark measures the update.
class OccupancyGrid {
 public:
  /// Clamping of the stored log-odds.
  struct Options {
    /// Lower clamp of a cell's log-odds (log(0.12 / 0.88)).
    double min_log_odds{-1.9924};
    /// Upper clamp of a cell's log-odds (log(0.97 / 0.03)).
    double max_log_odds{3.4761};
  };

  /// Most cells a grid may hold: 2^30 (4 GiB of log-odds).
  static constexpr std::int64_t kMaxCells = std::int64_t{1} << 30;

  /// A grid whose cell (0, 0, 0) has its minimum corner at `min_corner` (world frame), with `dims` cells of side
  /// `resolution` metres per axis, all at probability 0.5. Throws std::invalid_argument for a non-positive or
  /// non-finite resolution, a non-positive dimension, more than kMaxCells cells, a non-finite corner, or
  /// inverted or non-finite clamps.
  OccupancyGrid(const Eigen::Vector3d& min_corner, double resolution, const Eigen::Vector3i& dims,
                const Options& options);
  /// Same, with default clamps.
  OccupancyGrid(const Eigen::Vector3d& min_corner, double resolution, const Eigen::Vector3i& dims);

  const Eigen::Vector3d& min_corner() const { return min_corner_; }
  double resolution() const { return resolution_; }
  const Eigen::Vector3i& dims() const { return dims_; }
  std::size_t num_cells() const { return log_odds_.size(); }
  /// The maximum corner of the grid.
  Eigen::Vector3d max_corner() const { return min_corner_ + dims_.cast<double>() * resolution_; }

  /// The cell containing p_W, or nothing outside the grid.
  std::optional<Eigen::Vector3i> CellOf(const Eigen::Vector3d& p_W) const;
  /// Linear index of a cell (x fastest).
  std::size_t Index(const Eigen::Vector3i& cell) const {
    return (static_cast<std::size_t>(cell.z()) * dims_.y() + cell.y()) * dims_.x() + cell.x();
  }
  /// The cell of a linear index.
  Eigen::Vector3i Cell(std::size_t index) const;
  /// Centre of a cell in the world.
  Eigen::Vector3d CellCenter(const Eigen::Vector3i& cell) const {
    return min_corner_ + (cell.cast<double>() + Eigen::Vector3d::Constant(0.5)) * resolution_;
  }

  /// Stored log-odds of a cell.
  float log_odds(std::size_t index) const { return log_odds_[index]; }
  /// Occupancy probability of a cell.
  double probability(std::size_t index) const;
  /// Occupancy probability at a point; 0.5 (unknown) outside the grid.
  double Probability(const Eigen::Vector3d& p_W) const;

  /// Bayes update of one cell by a measurement's log-odds, then clamping.
  void Update(std::size_t index, float measurement_log_odds) {
    float& l = log_odds_[index];
    l = std::min(max_log_odds_, std::max(min_log_odds_, l + measurement_log_odds));
  }
  /// Resets every cell to probability 0.5.
  void Clear();

  /// Linear indices (ascending) of the cells with probability above `threshold`.
  std::vector<std::size_t> OccupiedCells(double threshold = 0.5) const;
  /// Centres of the occupied cells, in OccupiedCells() order.
  std::vector<Eigen::Vector3d> OccupiedPoints(double threshold = 0.5) const;

  /// Walks the ray origin + t direction for t in [t_begin, t_end] through the grid (3-D DDA, Amanatides-Woo),
  /// calling visit(index, t_enter, t_exit) for every cell crossed, in order (t_enter is the previous call's t_exit).
  /// Stops early when visit returns false. Where the ray passes exactly through an edge or corner, the cells it only
  /// touches there are not visited (see internal::GridWalk). A zero direction visits the cell of `origin` once.
  template <typename Visit>
  void Traverse(const Eigen::Vector3d& origin, const Eigen::Vector3d& direction, double t_begin, double t_end,
                const Visit& visit) const;

  /// The first cell centre with probability above `threshold` along the ray (direction need not be unit) within
  /// `max_range` metres, or nothing.
  std::optional<Eigen::Vector3d> CastRay(const Eigen::Vector3d& origin, const Eigen::Vector3d& direction,
                                         double max_range, double threshold = 0.5) const;

  /// The occupied cell centres (probability above `threshold`) as an ASCII PLY point cloud with a `probability`
  /// property, in cell order.
  std::string PlyText(double threshold = 0.5) const;

  /// Writes PlyText() to `path` atomically (an interrupted or failed write leaves an earlier file whole). Throws
  /// std::runtime_error naming the path if it cannot be written.
  void WritePly(const std::string& path, double threshold = 0.5) const;

 private:
  Eigen::Vector3d min_corner_;
  double resolution_;
  Eigen::Vector3i dims_;
  float min_log_odds_;
  float max_log_odds_;
  std::vector<float> log_odds_;
};

template <typename Visit>
void OccupancyGrid::Traverse(const Eigen::Vector3d& origin, const Eigen::Vector3d& direction, double t_begin,
                             double t_end, const Visit& visit) const {
  if (direction.isZero()) {  // the ray is a point
    const auto cell = CellOf(origin);
    if (cell && t_begin < t_end) visit(Index(*cell), t_begin, t_end);
    return;
  }
  internal::GridWalk walk;
  if (!walk.Start(min_corner_, resolution_, dims_, origin, direction, t_begin, t_end)) return;
  double t = walk.t_begin();
  const double unit = walk.unit();
  walk.Walk(std::numeric_limits<std::int64_t>::max(), [&](std::size_t index, std::int64_t exit) {
    const double t_exit = static_cast<double>(exit) * unit;
    const bool more = visit(index, t, t_exit);
    t = t_exit;
    return more;
  });
}

}  // namespace cairn::perception
