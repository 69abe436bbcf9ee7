#include <cairn/planning/footstep/terrain_map.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <utility>

#include <cairn/planning/footstep/internal/yaw_box.h>

namespace cairn::planning {

TerrainMap::TerrainMap(const Eigen::Vector2d& origin, int cols, int rows, double resolution)
    : origin_(origin), cols_(cols), rows_(rows), resolution_(resolution) {
  if (cols <= 0 || rows <= 0) {
    std::ostringstream message;
    message << "TerrainMap: the grid needs at least one cell, got " << cols << " x " << rows
            << " cells; give a positive size";
    throw std::invalid_argument(message.str());
  }
  if (!(resolution > 0.0) || !std::isfinite(resolution)) {
    std::ostringstream message;
    message << "TerrainMap: resolution must be a positive length in metres, got " << resolution;
    throw std::invalid_argument(message.str());
  }
  if (!origin.allFinite()) throw std::invalid_argument("TerrainMap: the origin must be finite");
  const std::int64_t cells = static_cast<std::int64_t>(cols) * rows;
  if (cells > kMaxCells) {
    std::ostringstream message;
    message << "TerrainMap: " << cols << " x " << rows << " = " << cells << " cells are more than the " << kMaxCells
            << " a map may hold (24 bytes each); coarsen the resolution or crop the map";
    throw std::invalid_argument(message.str());
  }
  const std::size_t n = static_cast<std::size_t>(cols) * static_cast<std::size_t>(rows);
  height_.assign(n, std::numeric_limits<float>::quiet_NaN());
  normal_.assign(3 * n, 0.0f);
  friction_.assign(n, 0.0f);
}

void TerrainMap::CheckCell(int col, int row, const char* caller) const {
  if (col < 0 || col >= cols_ || row < 0 || row >= rows_) {
    std::ostringstream message;
    message << "TerrainMap::" << caller << ": cell (" << col << ", " << row << ") is outside the " << cols_ << " x "
            << rows_ << " grid";
    throw std::out_of_range(message.str());
  }
}

void TerrainMap::SetCell(int col, int row, double height, const Eigen::Vector3d& normal, double friction) {
  CheckCell(col, row, "SetCell");
  if (!std::isfinite(height)) {
    std::ostringstream message;
    message << "TerrainMap::SetCell: height " << height << " of cell (" << col << ", " << row
            << ") is not finite; use ClearCell() for a cell without ground";
    throw std::invalid_argument(message.str());
  }
  if (!normal.allFinite() || std::abs(normal.norm() - 1.0) > 1e-6 || normal.z() <= 0.0) {
    std::ostringstream message;
    message << "TerrainMap::SetCell: normal (" << normal.transpose() << ") of cell (" << col << ", " << row
            << ") must be a unit vector pointing up (z > 0)";
    throw std::invalid_argument(message.str());
  }
  if (!(friction >= 0.0) || !std::isfinite(friction)) {
    std::ostringstream message;
    message << "TerrainMap::SetCell: friction " << friction << " of cell (" << col << ", " << row
            << ") must be a finite coefficient >= 0 (0 marks ground that is not walkable)";
    throw std::invalid_argument(message.str());
  }
  const std::size_t i = Index(col, row);
  height_[i] = static_cast<float>(height);
  for (int k = 0; k < 3; ++k) normal_[3 * i + k] = static_cast<float>(normal[k]);
  friction_[i] = static_cast<float>(friction);
}

void TerrainMap::ClearCell(int col, int row) {
  CheckCell(col, row, "ClearCell");
  const std::size_t i = Index(col, row);
  height_[i] = std::numeric_limits<float>::quiet_NaN();
  friction_[i] = 0.0f;
}

void TerrainMap::AddObstacle(const Obstacle& obstacle) {
  if (!obstacle.center.allFinite() || !std::isfinite(obstacle.yaw) || !(obstacle.half_extents.array() > 0.0).all()) {
    std::ostringstream message;
    message << "TerrainMap::AddObstacle: obstacle '" << obstacle.name << "' needs a finite centre and yaw and "
            << "positive half extents, got half extents (" << obstacle.half_extents.transpose() << ")";
    throw std::invalid_argument(message.str());
  }
  obstacles_.push_back(obstacle);
  // Cells whose centre lies inside the footprint lose their ground.
  const double c = std::cos(obstacle.yaw), s = std::sin(obstacle.yaw);
  const double rx = std::abs(c) * obstacle.half_extents.x() + std::abs(s) * obstacle.half_extents.y();
  const double ry = std::abs(s) * obstacle.half_extents.x() + std::abs(c) * obstacle.half_extents.y();
  const int c0 = std::max(0, static_cast<int>(std::floor((obstacle.center.x() - rx - origin_.x()) / resolution_)));
  const int c1 = std::min(cols_ - 1, static_cast<int>(std::floor((obstacle.center.x() + rx - origin_.x()) / resolution_)));
  const int r0 = std::max(0, static_cast<int>(std::floor((obstacle.center.y() - ry - origin_.y()) / resolution_)));
  const int r1 = std::min(rows_ - 1, static_cast<int>(std::floor((obstacle.center.y() + ry - origin_.y()) / resolution_)));
  for (int row = r0; row <= r1; ++row) {
    for (int col = c0; col <= c1; ++col) {
      const Eigen::Vector2d d = CellCenter(col, row) - obstacle.center.head<2>();
      const double lx = c * d.x() + s * d.y();
      const double ly = -s * d.x() + c * d.y();
      if (std::abs(lx) <= obstacle.half_extents.x() && std::abs(ly) <= obstacle.half_extents.y()) ClearCell(col, row);
    }
  }
}

bool TerrainMap::CellAt(double x, double y, int* col, int* row) const {
  const double fx = (x - origin_.x()) / resolution_;
  const double fy = (y - origin_.y()) / resolution_;
  if (!(fx >= 0.0 && fy >= 0.0 && fx < cols_ && fy < rows_)) return false;
  *col = static_cast<int>(fx);
  *row = static_cast<int>(fy);
  return true;
}

Eigen::Vector2d TerrainMap::CellCenter(int col, int row) const {
  return origin_ + resolution_ * Eigen::Vector2d(col + 0.5, row + 0.5);
}

Eigen::Vector3d TerrainMap::normal(int col, int row) const {
  const std::size_t i = Index(col, row);
  return Eigen::Vector3d(normal_[3 * i], normal_[3 * i + 1], normal_[3 * i + 2]);
}

bool TerrainMap::BoxHitsObstacle(const Eigen::Vector3d& center, const Eigen::Vector3d& half_extents, double yaw) const {
  for (const Obstacle& o : obstacles_) {
    if (internal::YawBoxesOverlap(center, half_extents, yaw, o.center, o.half_extents, o.yaw)) return true;
  }
  return false;
}

void TerrainMap::SetOccupiedVoxels(std::vector<OccupiedVoxel> voxels, double size) {
  if (!(size > 0.0) || !std::isfinite(size)) {
    std::ostringstream message;
    message << "TerrainMap::SetOccupiedVoxels: voxel size " << size << " m must be positive and finite";
    throw std::invalid_argument(message.str());
  }
  if (voxels.size() > kMaxVoxels) {
    std::ostringstream message;
    message << "TerrainMap::SetOccupiedVoxels: " << voxels.size() << " voxels are more than the " << kMaxVoxels
            << " a map may hold; raise the occupancy threshold or coarsen the grid";
    throw std::invalid_argument(message.str());
  }
  for (std::size_t i = 0; i < voxels.size(); ++i) {
    const OccupiedVoxel& v = voxels[i];
    if (!v.center.allFinite() || !(v.probability > 0.0 && v.probability <= 1.0)) {
      std::ostringstream message;
      message << "TerrainMap::SetOccupiedVoxels: voxel " << i << " at (" << v.center.transpose() << ") has probability "
              << v.probability << "; give a finite centre and a probability in (0, 1]";
      throw std::invalid_argument(message.str());
    }
  }
  voxels_ = std::move(voxels);
  voxel_size_ = voxels_.empty() ? 0.0 : size;
  // Buckets of at least 20 cm (a body box then spans a few of them) and at least a voxel.
  bucket_size_ = std::max({0.2, size, resolution_});
  bucket_cols_ = static_cast<int>(std::ceil(cols_ * resolution_ / bucket_size_));
  bucket_rows_ = static_cast<int>(std::ceil(rows_ * resolution_ / bucket_size_));
  const std::size_t buckets = static_cast<std::size_t>(bucket_cols_) * static_cast<std::size_t>(bucket_rows_);
  std::vector<int> bucket_of(voxels_.size(), -1);
  std::vector<int> count(buckets + 1, 0);
  voxel_outside_.clear();
  voxel_log_free_.resize(voxels_.size());
  for (std::size_t i = 0; i < voxels_.size(); ++i) {
    voxel_log_free_[i] = std::log1p(-voxels_[i].probability);
    const double bx = (voxels_[i].center.x() - origin_.x()) / bucket_size_;
    const double by = (voxels_[i].center.y() - origin_.y()) / bucket_size_;
    if (bx >= 0.0 && by >= 0.0 && bx < bucket_cols_ && by < bucket_rows_) {
      bucket_of[i] = static_cast<int>(by) * bucket_cols_ + static_cast<int>(bx);
      ++count[static_cast<std::size_t>(bucket_of[i]) + 1];
    } else {
      voxel_outside_.push_back(static_cast<int>(i));
    }
  }
  bucket_start_.assign(buckets + 1, 0);
  for (std::size_t b = 0; b < buckets; ++b) bucket_start_[b + 1] = bucket_start_[b] + count[b + 1];
  voxel_order_.assign(static_cast<std::size_t>(bucket_start_[buckets]), 0);
  std::vector<int> fill(bucket_start_.begin(), bucket_start_.end() - 1);
  for (std::size_t i = 0; i < voxels_.size(); ++i) {
    if (bucket_of[i] >= 0) voxel_order_[static_cast<std::size_t>(fill[static_cast<std::size_t>(bucket_of[i])]++)] = static_cast<int>(i);
  }
}

double TerrainMap::BoxFreeProbability(const Eigen::Vector3d& center, const Eigen::Vector3d& half_extents, double yaw,
                                      double stop_below) const {
  if (voxels_.empty()) return 1.0;
  // A voxel that only touches the box's surface does not count: shrink it by a hair.
  const double h = 0.5 * voxel_size_ * (1.0 - 1e-9);
  const double cos_yaw = std::cos(yaw), sin_yaw = std::sin(yaw);
  const double c = std::abs(cos_yaw), s = std::abs(sin_yaw);
  // Half widths of the box along the world axes, and of the voxel (an axis-aligned cube) along the box's axes.
  const double rx = c * half_extents.x() + s * half_extents.y();
  const double ry = s * half_extents.x() + c * half_extents.y();
  const double voxel_along_box = h * (c + s);
  const double log_stop = stop_below > 0.0 ? std::log(stop_below) : -std::numeric_limits<double>::infinity();
  double log_free = 0.0;
  // Separating axes of a yawed box and an axis-aligned cube: z, the world's x and y, and the box's two axes.
  auto visit = [&](int i) {
    const Eigen::Vector3d d = voxels_[static_cast<std::size_t>(i)].center - center;
    if (std::abs(d.z()) > half_extents.z() + h || std::abs(d.x()) > rx + h || std::abs(d.y()) > ry + h) return false;
    if (std::abs(cos_yaw * d.x() + sin_yaw * d.y()) > half_extents.x() + voxel_along_box) return false;
    if (std::abs(-sin_yaw * d.x() + cos_yaw * d.y()) > half_extents.y() + voxel_along_box) return false;
    log_free += voxel_log_free_[static_cast<std::size_t>(i)];
    return log_free < log_stop;
  };
  const int b0x = std::max(0, static_cast<int>(std::floor((center.x() - rx - h - origin_.x()) / bucket_size_)));
  const int b1x = std::min(bucket_cols_ - 1, static_cast<int>(std::floor((center.x() + rx + h - origin_.x()) / bucket_size_)));
  const int b0y = std::max(0, static_cast<int>(std::floor((center.y() - ry - h - origin_.y()) / bucket_size_)));
  const int b1y = std::min(bucket_rows_ - 1, static_cast<int>(std::floor((center.y() + ry + h - origin_.y()) / bucket_size_)));
  for (int by = b0y; by <= b1y; ++by) {
    for (int bx = b0x; bx <= b1x; ++bx) {
      const std::size_t b = static_cast<std::size_t>(by) * static_cast<std::size_t>(bucket_cols_) + static_cast<std::size_t>(bx);
      for (int k = bucket_start_[b]; k < bucket_start_[b + 1]; ++k) {
        if (visit(voxel_order_[static_cast<std::size_t>(k)])) return std::exp(log_free);
      }
    }
  }
  for (const int i : voxel_outside_) {
    if (visit(i)) return std::exp(log_free);
  }
  return std::exp(log_free);
}

bool TerrainMap::DiscMeetsVoxel(const Eigen::Vector2d& center, double radius, double z_lo, double z_hi,
                                double free_below) const {
  if (voxels_.empty()) return false;
  const double h = 0.5 * voxel_size_;
  const double log_below = std::log(free_below);
  auto meets = [&](int i) {
    if (!(voxel_log_free_[static_cast<std::size_t>(i)] < log_below)) return false;
    const Eigen::Vector3d& v = voxels_[static_cast<std::size_t>(i)].center;
    if (v.z() + h <= z_lo || v.z() - h >= z_hi) return false;
    const double gx = std::max(0.0, std::abs(v.x() - center.x()) - h);
    const double gy = std::max(0.0, std::abs(v.y() - center.y()) - h);
    return gx * gx + gy * gy < radius * radius;
  };
  const double reach = radius + h;
  const int b0x = std::max(0, static_cast<int>(std::floor((center.x() - reach - origin_.x()) / bucket_size_)));
  const int b1x = std::min(bucket_cols_ - 1, static_cast<int>(std::floor((center.x() + reach - origin_.x()) / bucket_size_)));
  const int b0y = std::max(0, static_cast<int>(std::floor((center.y() - reach - origin_.y()) / bucket_size_)));
  const int b1y = std::min(bucket_rows_ - 1, static_cast<int>(std::floor((center.y() + reach - origin_.y()) / bucket_size_)));
  for (int by = b0y; by <= b1y; ++by) {
    for (int bx = b0x; bx <= b1x; ++bx) {
      const std::size_t b = static_cast<std::size_t>(by) * static_cast<std::size_t>(bucket_cols_) + static_cast<std::size_t>(bx);
      for (int k = bucket_start_[b]; k < bucket_start_[b + 1]; ++k) {
        if (meets(voxel_order_[static_cast<std::size_t>(k)])) return true;
      }
    }
  }
  for (const int i : voxel_outside_) {
    if (meets(i)) return true;
  }
  return false;
}

}  // namespace cairn::planning
