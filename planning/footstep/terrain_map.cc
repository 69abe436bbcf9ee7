#include <cairn/planning/footstep/terrain_map.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <sstream>
#include <stdexcept>

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

}  // namespace cairn::planning
