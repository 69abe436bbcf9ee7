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
///
/// Besides certain box obstacles, the map may hold perception's uncertain evidence of occupied space: cubic
/// voxels each occupied with a probability, independently of the others (an occupancy grid's own assumption). The
/// probability that a body box is free is then the product of (1 - p) over the voxels it overlaps, and a planner
/// allows a stance only when that stays above its level eta_geom (FootstepPlannerOptions::min_body_free_probability).
class TerrainMap {
 public:
  /// An axis-aligned box in the horizontal plane rotated by `yaw` about its centre's vertical axis.
  struct Obstacle {
    std::string name;
    Eigen::Vector3d center{Eigen::Vector3d::Zero()};
    Eigen::Vector3d half_extents{Eigen::Vector3d::Zero()};
    double yaw{0.0};
  };

  /// A cube of occupied space with its occupancy probability (from an occupancy grid's cell).
  struct OccupiedVoxel {
    Eigen::Vector3d center{Eigen::Vector3d::Zero()};
    double probability{0.5};
  };

  /// Most cells a map may hold: 2^27 (3 GiB).
  static constexpr std::int64_t kMaxCells = std::int64_t{1} << 27;
  /// Most occupied voxels a map may hold: 2^24.
  static constexpr std::size_t kMaxVoxels = std::size_t{1} << 24;

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

  /// Replaces the occupied voxels by `voxels`, cubes of side `size` (m). Unlike AddObstacle, voxels leave the
  /// ground below them as it is (a foot's support is the ground cells' business; voxels only block bodies). Throws
  /// std::invalid_argument for a non-positive or non-finite size, a voxel whose probability is outside (0, 1] or
  /// whose centre is not finite (naming its index), or more than kMaxVoxels voxels.
  void SetOccupiedVoxels(std::vector<OccupiedVoxel> voxels, double size);
  /// The occupied voxels, in the order given.
  const std::vector<OccupiedVoxel>& occupied_voxels() const { return voxels_; }
  /// Side of the occupied voxels, m (0 when there are none).
  double voxel_size() const { return voxel_size_; }
  /// The probability that the box `half_extents` centred at `center`, rotated by `yaw`, overlaps no occupied
  /// voxel: the product of (1 - p) over the voxels whose cube overlaps the box's interior (1 without voxels).
  /// With `stop_below` > 0 the product stops once it falls below that value (the result is then below it too,
  /// not the full product): a planner asking "at least eta?" needs no more.
  double BoxFreeProbability(const Eigen::Vector3d& center, const Eigen::Vector3d& half_extents, double yaw,
                            double stop_below = 0.0) const;
  /// Whether a voxel that alone leaves a box free with probability below `free_below` (1 - p < free_below) has a
  /// footprint within `radius` of `center` and overlaps the heights (z_lo, z_hi): for a planner's admissible
  /// bounds, such a voxel is as certain an obstacle as a box.
  bool DiscMeetsVoxel(const Eigen::Vector2d& center, double radius, double z_lo, double z_hi, double free_below) const;

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
  // Occupied voxels, and their log(1 - p) bucketed on a coarse grid of `bucket_size_` squares from origin_
  // (CSR: the voxels of bucket b are voxel_order_[bucket_start_[b] .. bucket_start_[b + 1])); voxels outside the
  // bucket grid are listed in voxel_outside_ and checked by every query.
  std::vector<OccupiedVoxel> voxels_;
  double voxel_size_{0.0};
  double bucket_size_{0.0};
  int bucket_cols_{0};
  int bucket_rows_{0};
  std::vector<int> bucket_start_;
  std::vector<int> voxel_order_;
  std::vector<int> voxel_outside_;
  std::vector<double> voxel_log_free_;
};

}  // namespace cairn::planning
