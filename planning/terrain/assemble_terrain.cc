#include <cairn/planning/terrain/assemble_terrain.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <cairn/common/number_text.h>

namespace cairn::planning {

namespace {
void Require(bool ok, const char* name, double value, const char* range) {
  if (!ok) {
    throw std::invalid_argument(std::string("TerrainAssemblyOptions: ") + name + " is " + FormatShort(value) +
                                "; it must be " + range);
  }
}
}  // namespace

void ValidateTerrainAssemblyOptions(const TerrainAssemblyOptions& o) {
  Require(o.occupied_threshold >= 0.0 && o.occupied_threshold < 1.0, "occupied_threshold", o.occupied_threshold,
          "in [0, 1)");
  Require(std::isfinite(o.max_ground_height), "max_ground_height", o.max_ground_height, "finite (world z, m)");
  Require(o.eta > 0.0 && o.eta < 1.0, "eta", o.eta, "in (0, 1)");
  Require(o.min_points >= 1 && o.min_points <= 1000000, "min_points", o.min_points, "in [1, 1000000]");
  Require(o.unknown_friction >= 0.0 && o.unknown_friction <= 10.0, "unknown_friction", o.unknown_friction,
          "in [0, 10] (0: not walkable)");
}

TerrainMap AssembleTerrain(const perception::OccupancyGrid& grid, const perception::FrictionPointCloud& points,
                           const perception::MaterialRegistry& registry, const TerrainAssemblyOptions& options) {
  ValidateTerrainAssemblyOptions(options);
  const int labels = registry.size();
  if (points.weights.rows() != points.size() || (points.size() > 0 && points.weights.cols() != labels) ||
      points.quantiles.size() != points.points_W.size()) {
    throw std::invalid_argument("AssembleTerrain: the friction points have " + FormatShort(points.size()) +
                                " points, " + FormatShort(points.quantiles.size()) + " quantiles and " +
                                FormatShort(points.weights.rows()) + " x " + FormatShort(points.weights.cols()) +
                                " weights; give one quantile and one row of " + FormatShort(labels) +
                                " registry-order weights per point");
  }
  const Eigen::Vector3i& dims = grid.dims();
  const double res = grid.resolution();
  const Eigen::Vector3d& corner = grid.min_corner();
  const int cols = dims.x(), rows = dims.y(), layers = dims.z();
  const std::size_t columns = static_cast<std::size_t>(cols) * static_cast<std::size_t>(rows);
  TerrainMap terrain(corner.head<2>(), cols, rows, res);

  // The points inside the grid with their column and layer, grouped by column (in their order: the same bytes out).
  struct ColumnPoint {
    std::size_t column;
    int layer;
    int index;
  };
  // Counting sort by column: two passes over the points, in their order within a column.
  std::vector<ColumnPoint> cells;
  cells.reserve(static_cast<std::size_t>(points.size()));
  std::vector<std::size_t> first(columns + 1, 0);
  for (int i = 0; i < points.size(); ++i) {
    const std::optional<Eigen::Vector3i> cell = grid.CellOf(points.points_W[static_cast<std::size_t>(i)]);
    if (!cell) continue;
    const std::size_t column =
        static_cast<std::size_t>(cell->y()) * static_cast<std::size_t>(cols) + static_cast<std::size_t>(cell->x());
    cells.push_back({column, cell->z(), i});
    ++first[column + 1];
  }
  for (std::size_t column = 0; column < columns; ++column) first[column + 1] += first[column];
  std::vector<ColumnPoint> located(cells.size());
  std::vector<std::size_t> next(first.begin(), first.end() - 1);
  for (const ColumnPoint& p : cells) located[next[p.column]++] = p;

  // The ground of each column: the highest occupied layer (centre at most max_ground_height) that its surface's
  // points confirm -- at least min_points of them within one layer of it -- else the highest occupied layer, then
  // without points. A surface on a layer boundary spreads its points over two layers, and a single stereo frame
  // leaves cells a few centimetres above the floor occupied by mismatches: the points, which lie on the surface
  // itself, tell the floor from those (measured on the mock-up's floor: without them half of the wood's cells had
  // no friction and some stood 5-7.5 cm high). The cells above the ground stay obstacles below, with their
  // probability. Per column: the ground layer, its points' heights and summed mixtures.
  std::vector<int> ground_layer(columns, -1);
  std::vector<std::vector<float>> heights(columns);
  Eigen::MatrixXd mixture = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(columns), labels);
  std::vector<int> count(columns, 0);
  auto near = [](int layer, int ground) { return layer >= ground - 1 && layer <= ground + 1; };
  for (int r = 0; r < rows; ++r) {
    for (int c = 0; c < cols; ++c) {
      const std::size_t column = static_cast<std::size_t>(r) * static_cast<std::size_t>(cols) + static_cast<std::size_t>(c);
      int top = -1, confirmed = -1;
      for (int k = layers - 1; k >= 0 && confirmed < 0; --k) {
        if (corner.z() + (k + 0.5) * res > options.max_ground_height) continue;
        if (grid.probability(grid.Index(Eigen::Vector3i(c, r, k))) <= options.occupied_threshold) continue;
        if (top < 0) top = k;
        int n = 0;
        for (std::size_t j = first[column]; j < first[column + 1]; ++j) n += near(located[j].layer, k) ? 1 : 0;
        if (n >= options.min_points) confirmed = k;
      }
      const int ground = confirmed >= 0 ? confirmed : top;
      ground_layer[column] = ground;
      if (ground < 0) continue;
      for (std::size_t j = first[column]; j < first[column + 1]; ++j) {
        if (!near(located[j].layer, ground)) continue;
        const int i = located[j].index;
        heights[column].push_back(static_cast<float>(points.points_W[static_cast<std::size_t>(i)].z()));
        mixture.row(static_cast<Eigen::Index>(column)) += points.weights.row(i).cast<double>();
        ++count[column];
      }
    }
  }

  std::vector<double> height(columns, std::numeric_limits<double>::quiet_NaN());
  for (std::size_t column = 0; column < columns; ++column) {
    if (ground_layer[column] < 0) continue;
    std::vector<float>& h = heights[column];
    if (h.empty()) {
      height[column] = corner.z() + (ground_layer[column] + 1) * res;
    } else {
      const auto middle = h.begin() + static_cast<std::ptrdiff_t>(h.size() / 2);
      std::nth_element(h.begin(), middle, h.end());
      height[column] = *middle;
    }
  }
  auto height_at = [&](int c, int r) {
    if (c < 0 || r < 0 || c >= cols || r >= rows) return std::numeric_limits<double>::quiet_NaN();
    return height[static_cast<std::size_t>(r) * static_cast<std::size_t>(cols) + static_cast<std::size_t>(c)];
  };
  // d height / d axis at (c, r) from its neighbours along (dc, dr): central where both have ground.
  auto slope = [&](int c, int r, int dc, int dr) {
    const double here = height_at(c, r), ahead = height_at(c + dc, r + dr), behind = height_at(c - dc, r - dr);
    if (!std::isnan(ahead) && !std::isnan(behind)) return (ahead - behind) / (2.0 * res);
    if (!std::isnan(ahead)) return (ahead - here) / res;
    if (!std::isnan(behind)) return (here - behind) / res;
    return 0.0;
  };
  Eigen::VectorXd weights(labels);
  for (int r = 0; r < rows; ++r) {
    for (int c = 0; c < cols; ++c) {
      const std::size_t column = static_cast<std::size_t>(r) * static_cast<std::size_t>(cols) + static_cast<std::size_t>(c);
      if (std::isnan(height[column])) continue;
      const Eigen::Vector3d normal = Eigen::Vector3d(-slope(c, r, 1, 0), -slope(c, r, 0, 1), 1.0).normalized();
      double friction = options.unknown_friction;
      if (count[column] >= options.min_points) {
        weights = mixture.row(static_cast<Eigen::Index>(column)).transpose();
        const double total = weights.sum();
        if (total > 0.0) {
          weights /= total;
          friction = perception::FrictionQuantile(registry, weights, options.eta, options.quantile_method);
        }
      }
      terrain.SetCell(c, r, height[column], normal, friction);
    }
  }

  // Everything occupied above the ground cell is an obstacle for the body, with its probability.
  std::vector<TerrainMap::OccupiedVoxel> voxels;
  for (int r = 0; r < rows; ++r) {
    for (int c = 0; c < cols; ++c) {
      const std::size_t column = static_cast<std::size_t>(r) * static_cast<std::size_t>(cols) + static_cast<std::size_t>(c);
      for (int k = ground_layer[column] + 1; k < layers; ++k) {
        const Eigen::Vector3i cell(c, r, k);
        const double p = grid.probability(grid.Index(cell));
        if (p <= options.occupied_threshold) continue;
        if (voxels.size() >= TerrainMap::kMaxVoxels) {
          throw std::invalid_argument("AssembleTerrain: more than " + FormatShort(TerrainMap::kMaxVoxels) +
                                      " occupied cells above the ground; raise occupied_threshold or coarsen the grid");
        }
        voxels.push_back({grid.CellCenter(cell), p});
      }
    }
  }
  terrain.SetOccupiedVoxels(std::move(voxels), res);
  return terrain;
}

}  // namespace cairn::planning
