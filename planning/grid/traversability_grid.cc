#include "cairn/planning/grid/traversability_grid.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include "cairn/common/number_text.h"

namespace cairn::planning {

Eigen::Vector2i TraversabilityGrid::CellOf(const Eigen::Vector2d& p_W) const {
  const Eigen::Vector2d offset = (p_W - min_corner) / resolution;
  if (!offset.allFinite()) return Eigen::Vector2i(-1, -1);
  const Eigen::Vector2d f = offset.array().floor();
  if (f.x() < 0 || f.y() < 0 || f.x() >= rows() || f.y() >= cols()) return Eigen::Vector2i(-1, -1);
  return f.cast<int>();
}

void TraversabilityGrid::Validate() const {
  if (values.size() == 0) throw std::invalid_argument("TraversabilityGrid: the grid has no cells");
  if (static_cast<std::int64_t>(values.rows()) * values.cols() > kMaxCells) {
    throw std::invalid_argument("TraversabilityGrid: " + FormatShort(static_cast<long>(values.rows())) + " x " +
                                FormatShort(static_cast<long>(values.cols())) + " cells exceed the limit of " +
                                FormatShort(static_cast<long long>(kMaxCells)));
  }
  if (!(resolution > 0.0) || !std::isfinite(resolution)) {
    throw std::invalid_argument("TraversabilityGrid: resolution " + FormatShort(resolution) +
                                " m must be positive and finite");
  }
  if (!min_corner.allFinite()) throw std::invalid_argument("TraversabilityGrid: the minimum corner must be finite");
  for (int i = 0; i < rows(); ++i) {
    for (int j = 0; j < cols(); ++j) {
      const double t = values(i, j);
      if (!std::isnan(t) && !(t >= 0.0 && t <= 1.0)) {
        throw std::invalid_argument("TraversabilityGrid: traversability " + FormatShort(t) + " at cell (" +
                                    FormatShort(i) + ", " + FormatShort(j) + ") is not in [0, 1] (or NaN = unknown)");
      }
    }
  }
}

}  // namespace cairn::planning
