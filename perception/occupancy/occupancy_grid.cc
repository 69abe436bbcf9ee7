#include "cairn/perception/occupancy/occupancy_grid.h"

#include <cmath>
#include <cstdint>
#include <sstream>
#include <stdexcept>
#include <string>

#include "cairn/common/atomic_file.h"
#include "cairn/common/number_text.h"

namespace cairn::perception {

OccupancyGrid::OccupancyGrid(const Eigen::Vector3d& min_corner, double resolution, const Eigen::Vector3i& dims)
    : OccupancyGrid(min_corner, resolution, dims, Options{}) {}

OccupancyGrid::OccupancyGrid(const Eigen::Vector3d& min_corner, double resolution, const Eigen::Vector3i& dims,
                             const Options& options)
    : min_corner_(min_corner),
      resolution_(resolution),
      dims_(dims),
      min_log_odds_(static_cast<float>(options.min_log_odds)),
      max_log_odds_(static_cast<float>(options.max_log_odds)) {
  if (!(resolution > 0.0) || !std::isfinite(resolution)) {
    throw std::invalid_argument("OccupancyGrid: resolution " + FormatShort(resolution) +
                                " m must be positive and finite (e.g. 0.05 for 5 cm cells)");
  }
  if (!min_corner.allFinite()) throw std::invalid_argument("OccupancyGrid: the minimum corner must be finite");
  const std::string size = cairn::FormatShort(dims.x()) + "x" + cairn::FormatShort(dims.y()) + "x" + cairn::FormatShort(dims.z());
  if (dims.minCoeff() <= 0) {
    throw std::invalid_argument("OccupancyGrid: dimensions " + size + " must all be positive");
  }
  // In double: the product of three ints overflows even 64 bits (2^31 cubed); a double is exact far beyond the
  // limit and only rounds counts that are refused anyway.
  const double cells = static_cast<double>(dims.x()) * dims.y() * dims.z();
  if (cells > static_cast<double>(kMaxCells)) {
    throw std::invalid_argument("OccupancyGrid: dimensions " + size + " are " + cairn::FormatShort(cells) +
                                " cells, more than the " + cairn::FormatShort(kMaxCells) +
                                " a grid may hold; coarsen the resolution or shrink the extent");
  }
  if (!(options.min_log_odds < 0.0 && options.max_log_odds > 0.0) || !std::isfinite(options.min_log_odds) ||
      !std::isfinite(options.max_log_odds)) {
    throw std::invalid_argument("OccupancyGrid: log-odds clamps [" + FormatShort(options.min_log_odds) + ", " +
                                FormatShort(options.max_log_odds) +
                                "] must be finite and straddle 0 (probability 0.5), e.g. [-2, 3.5]");
  }
  log_odds_.assign(static_cast<std::size_t>(dims.x()) * dims.y() * dims.z(), 0.0f);
}

std::optional<Eigen::Vector3i> OccupancyGrid::CellOf(const Eigen::Vector3d& p_W) const {
  const Eigen::Vector3d local = (p_W - min_corner_) / resolution_;
  Eigen::Vector3i cell;
  for (int a = 0; a < 3; ++a) {
    const double f = std::floor(local[a]);
    if (f < 0.0 || f >= dims_[a]) return std::nullopt;
    cell[a] = static_cast<int>(f);
  }
  return cell;
}

Eigen::Vector3i OccupancyGrid::Cell(std::size_t index) const {
  const auto nx = static_cast<std::size_t>(dims_.x());
  const auto ny = static_cast<std::size_t>(dims_.y());
  return Eigen::Vector3i(static_cast<int>(index % nx), static_cast<int>((index / nx) % ny),
                         static_cast<int>(index / (nx * ny)));
}

double OccupancyGrid::probability(std::size_t index) const {
  return 1.0 / (1.0 + std::exp(-static_cast<double>(log_odds_[index])));
}

double OccupancyGrid::Probability(const Eigen::Vector3d& p_W) const {
  const auto cell = CellOf(p_W);
  return cell ? probability(Index(*cell)) : 0.5;
}

void OccupancyGrid::Clear() { std::fill(log_odds_.begin(), log_odds_.end(), 0.0f); }

std::vector<std::size_t> OccupancyGrid::OccupiedCells(double threshold) const {
  const auto limit = static_cast<float>(std::log(threshold / (1.0 - threshold)));
  std::vector<std::size_t> cells;
  for (std::size_t i = 0; i < log_odds_.size(); ++i) {
    if (log_odds_[i] > limit) cells.push_back(i);
  }
  return cells;
}

std::vector<Eigen::Vector3d> OccupancyGrid::OccupiedPoints(double threshold) const {
  std::vector<Eigen::Vector3d> points;
  for (std::size_t i : OccupiedCells(threshold)) points.push_back(CellCenter(Cell(i)));
  return points;
}

std::optional<Eigen::Vector3d> OccupancyGrid::CastRay(const Eigen::Vector3d& origin, const Eigen::Vector3d& direction,
                                                      double max_range, double threshold) const {
  const double norm = direction.norm();
  if (!(norm > 0.0)) {
    throw std::invalid_argument("OccupancyGrid::CastRay: the direction is zero; give the ray's direction");
  }
  const auto limit = static_cast<float>(std::log(threshold / (1.0 - threshold)));
  std::optional<Eigen::Vector3d> hit;
  Traverse(origin, direction / norm, 0.0, max_range, [&](std::size_t index, double, double) {
    if (log_odds_[index] > limit) {
      hit = CellCenter(Cell(index));
      return false;
    }
    return true;
  });
  return hit;
}

std::string OccupancyGrid::PlyText(double threshold) const {
  const std::vector<std::size_t> cells = OccupiedCells(threshold);
  std::ostringstream out;
  out << "ply\nformat ascii 1.0\nelement vertex " << cells.size()
      << "\nproperty float x\nproperty float y\nproperty float z\nproperty float probability\nend_header\n";
  for (const std::size_t i : cells) {
    const Eigen::Vector3d p = CellCenter(Cell(i));
    out << p.x() << " " << p.y() << " " << p.z() << " " << probability(i) << "\n";
  }
  return out.str();
}

void OccupancyGrid::WritePly(const std::string& path, double threshold) const {
  // Atomic: an interrupted or failed write leaves an earlier file at `path` whole.
  WriteFileAtomically(path, PlyText(threshold));
}

}  // namespace cairn::perception
