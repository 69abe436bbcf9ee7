#pragma once

/// @file
/// A dense 3-D occupancy grid in log-odds.

#include <algorithm>
#include <cstddef>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

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

  /// A grid whose cell (0, 0, 0) has its minimum corner at `min_corner` (world frame), with `dims` cells of side
  /// `resolution` metres per axis, all at probability 0.5. Throws std::invalid_argument for a non-positive
  /// resolution or dimension, or inverted clamps.
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
  /// calling visit(index, t_enter, t_exit) for every cell crossed, in order. Stops early when visit returns false.
  template <typename Visit>
  void Traverse(const Eigen::Vector3d& origin, const Eigen::Vector3d& direction, double t_begin, double t_end,
                const Visit& visit) const;

  /// The first cell centre with probability above `threshold` along the ray (direction need not be unit) within
  /// `max_range` metres, or nothing.
  std::optional<Eigen::Vector3d> CastRay(const Eigen::Vector3d& origin, const Eigen::Vector3d& direction,
                                         double max_range, double threshold = 0.5) const;

  /// Writes the occupied cell centres as an ASCII PLY point cloud with a `probability` property. Throws
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
  // Clip [t_begin, t_end] to the grid's box (slabs).
  const Eigen::Vector3d hi = max_corner();
  double t0 = t_begin;
  double t1 = t_end;
  for (int a = 0; a < 3; ++a) {
    if (direction[a] == 0.0) {
      if (origin[a] < min_corner_[a] || origin[a] >= hi[a]) return;
      continue;
    }
    double ta = (min_corner_[a] - origin[a]) / direction[a];
    double tb = (hi[a] - origin[a]) / direction[a];
    if (ta > tb) std::swap(ta, tb);
    t0 = std::max(t0, ta);
    t1 = std::min(t1, tb);
  }
  if (!(t0 < t1)) return;
  const Eigen::Vector3d start = origin + t0 * direction;
  // Per axis: the t of the next boundary, the t between boundaries, the linear-index stride of a step and the
  // steps left before the ray leaves the grid. Which axis steps next changes irregularly along a ray, so the walk
  // chooses it with selects on registers rather than branches: a mispredicted branch per cell used to cost more
  // than the rest of the step.
  double t_max[3];
  double t_delta[3];
  std::ptrdiff_t stride[3];
  std::ptrdiff_t steps_left[3];
  std::ptrdiff_t index = 0;
  const std::ptrdiff_t axis_stride[3] = {1, dims_.x(), static_cast<std::ptrdiff_t>(dims_.x()) * dims_.y()};
  for (int a = 0; a < 3; ++a) {
    const int cell = std::min(dims_[a] - 1, std::max(0, static_cast<int>((start[a] - min_corner_[a]) / resolution_)));
    index += cell * axis_stride[a];
    if (direction[a] > 0.0) {
      stride[a] = axis_stride[a];
      steps_left[a] = dims_[a] - 1 - cell;
      t_max[a] = (min_corner_[a] + (cell + 1) * resolution_ - origin[a]) / direction[a];
      t_delta[a] = resolution_ / direction[a];
    } else if (direction[a] < 0.0) {
      stride[a] = -axis_stride[a];
      steps_left[a] = cell;
      t_max[a] = (min_corner_[a] + cell * resolution_ - origin[a]) / direction[a];
      t_delta[a] = -resolution_ / direction[a];
    } else {
      stride[a] = 0;
      steps_left[a] = std::numeric_limits<std::ptrdiff_t>::max();
      t_max[a] = std::numeric_limits<double>::infinity();
      t_delta[a] = std::numeric_limits<double>::infinity();
    }
  }
  double tx = t_max[0], ty = t_max[1], tz = t_max[2];
  std::ptrdiff_t nx = steps_left[0], ny = steps_left[1], nz = steps_left[2];
  double t = t0;
  while (t < t1) {
    // The axis whose boundary comes first; ties go to the later axis (y over x, z over both).
    const bool x_first = tx < ty;
    const double t_xy = x_first ? tx : ty;
    const bool xy_first = t_xy < tz;
    const double t_exit = std::min(xy_first ? t_xy : tz, t1);
    if (t_exit > t && !visit(static_cast<std::size_t>(index), t, t_exit)) return;
    t = t_exit;
    const bool step_x = x_first && xy_first;
    const bool step_y = !x_first && xy_first;
    const bool step_z = !xy_first;
    tx += step_x ? t_delta[0] : 0.0;
    ty += step_y ? t_delta[1] : 0.0;
    tz += step_z ? t_delta[2] : 0.0;
    index += step_x ? stride[0] : (step_y ? stride[1] : stride[2]);
    nx -= step_x;
    ny -= step_y;
    nz -= step_z;
    if ((nx | ny | nz) < 0) return;  // left the grid
  }
}

}  // namespace cairn::perception
