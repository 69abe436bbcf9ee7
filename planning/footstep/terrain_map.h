#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <Eigen/Core>

namespace cairn::planning {

/// Friction-annotated terrain for footstep planning: a 2.5-D grid of ground cells, each with a height, a surface
/// normal and the friction the planner may use there, plus box obstacles the body must not touch.
///
/// The friction of a cell is already the chance-constrained value `Q_{1-eta}(mu)` of the thesis (eq. 5.3): the
/// planner compares it directly with a step's RCOF. A cell with no ground (a hole, outside the mapped area) or
/// with friction 0 (water, sand, sky: "not walkable") never carries a foot.
///
/// Cells are addressed by (col, row); cell (c, r) covers x in [origin.x + c*res, origin.x + (c+1)*res) and
/// likewise y with r. Point queries use the cell containing the point.
class TerrainMap {
 public:
  /// An axis-aligned box in the horizontal plane rotated by `yaw` about its centre's vertical axis.
  struct Obstacle {
    std::string name;
    Eigen::Vector3d center{Eigen::Vector3d::Zero()};
    Eigen::Vector3d half_extents{Eigen::Vector3d::Zero()};
    double yaw{0.0};
  };

  /// Most cells a map may hold: 2^27 (3 GiB).
  static constexpr std::int64_t kMaxCells = std::int64_t{1} << 27;

  /// A grid of `cols` x `rows` cells of side `resolution` (m) whose minimum corner is `origin` (m), every cell
  /// without ground. Throws std::invalid_argument for a non-positive size or resolution, a non-finite origin, or
  /// more than kMaxCells cells.
  TerrainMap(const Eigen::Vector2d& origin, int cols, int rows, double resolution);

  /// Puts ground in cell (col, row). `normal` must be a unit vector pointing up (z > 0); `friction` >= 0.
  void SetCell(int col, int row, double height, const Eigen::Vector3d& normal, double friction);
  /// Removes the ground of cell (col, row).
  void ClearCell(int col, int row);
  /// Adds a box obstacle; the cells under its footprint lose their ground (a foot cannot stand inside it).
  void AddObstacle(const Obstacle& obstacle);

  const Eigen::Vector2d& origin() const { return origin_; }
  int cols() const { return cols_; }
  int rows() const { return rows_; }
  double resolution() const { return resolution_; }
  /// Minimum and maximum corners of the mapped area.
  Eigen::Vector2d min_corner() const { return origin_; }
  Eigen::Vector2d max_corner() const { return origin_ + resolution_ * Eigen::Vector2d(cols_, rows_); }
  const std::vector<Obstacle>& obstacles() const { return obstacles_; }

  /// The cell containing (x, y); false when the point lies outside the grid.
  bool CellAt(double x, double y, int* col, int* row) const;
  /// Centre of cell (col, row).
  Eigen::Vector2d CellCenter(int col, int row) const;

  bool has_ground(int col, int row) const { return height_[Index(col, row)] == height_[Index(col, row)]; }
  /// Height of the ground; NaN where there is none.
  double height(int col, int row) const { return height_[Index(col, row)]; }
  Eigen::Vector3d normal(int col, int row) const;
  double friction(int col, int row) const { return friction_[Index(col, row)]; }
  /// Ground present and friction above zero.
  bool walkable(int col, int row) const { return has_ground(col, row) && friction(col, row) > 0.0; }

  /// Whether the box `half_extents` centred at `center` and rotated by `yaw` overlaps an obstacle.
  bool BoxHitsObstacle(const Eigen::Vector3d& center, const Eigen::Vector3d& half_extents, double yaw) const;

 private:
  std::size_t Index(int col, int row) const { return static_cast<std::size_t>(row) * cols_ + col; }
  void CheckCell(int col, int row, const char* caller) const;

  Eigen::Vector2d origin_;
  int cols_;
  int rows_;
  double resolution_;
  std::vector<float> height_;
  std::vector<float> normal_;  // 3 per cell
  std::vector<float> friction_;
  std::vector<Obstacle> obstacles_;
};

}  // namespace cairn::planning
