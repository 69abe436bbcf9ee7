#include <cairn/planning/terrain/assemble_terrain.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
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

// Removes the ground of the cells TerrainAssemblyOptions::outlier_height names, judged on the ground as perceived
// (a window of fewer than 3 cells judges nothing), and marks in `raised` those that stood above their window's
// median: something standing on the floor, too narrow for the window, which must stay an obstacle, not be bridged.
void RemoveHeightOutliers(int cols, int rows, double res, const TerrainAssemblyOptions& options,
                          std::vector<double>* height, std::vector<char>* raised) {
  const std::vector<double> seen = *height;
  const int k = std::clamp(static_cast<int>(std::floor(std::min(options.outlier_radius / res, 1e6) + 1e-9)), 1,
                           std::max(cols, rows));
  std::vector<double> window;
  for (int r = 0; r < rows; ++r) {
    for (int c = 0; c < cols; ++c) {
      const std::size_t column = static_cast<std::size_t>(r) * static_cast<std::size_t>(cols) + static_cast<std::size_t>(c);
      if (std::isnan(seen[column])) continue;
      window.clear();
      for (int rr = std::max(0, r - k); rr <= std::min(rows - 1, r + k); ++rr) {
        for (int cc = std::max(0, c - k); cc <= std::min(cols - 1, c + k); ++cc) {
          const double h = seen[static_cast<std::size_t>(rr) * static_cast<std::size_t>(cols) + static_cast<std::size_t>(cc)];
          if (!std::isnan(h)) window.push_back(h);
        }
      }
      if (window.size() < 3) continue;
      const auto middle = window.begin() + static_cast<std::ptrdiff_t>(window.size() / 2);
      std::nth_element(window.begin(), middle, window.end());
      if (options.outlier_height > 0.0 && std::abs(seen[column] - *middle) > options.outlier_height) {
        (*height)[column] = std::nan("");
        (*raised)[column] = seen[column] > *middle ? 1 : 0;
      } else if (options.median_heights) {
        (*height)[column] = *middle;
      }
    }
  }
}

// Bridges the gaps of TerrainAssemblyOptions::max_gap in place, except the cells `raised` marks. Every gap cell is
// decided on the ground as perceived (bridged cells do not bridge further), along the axis whose two sides lie
// closer together.
void BridgeGaps(int cols, int rows, double res, const TerrainAssemblyOptions& options, const std::vector<char>& raised,
                std::vector<double>* height, std::vector<double>* friction) {
  const std::vector<double> seen_height = *height;
  const std::vector<double> seen_friction = *friction;
  const int reach = static_cast<int>(std::floor(std::min(options.max_gap / res, static_cast<double>(std::max(cols, rows))) + 1e-9));
  auto index = [cols](int c, int r) { return static_cast<std::size_t>(r) * static_cast<std::size_t>(cols) + static_cast<std::size_t>(c); };
  auto has = [&](int c, int r) { return c >= 0 && r >= 0 && c < cols && r < rows && !std::isnan(seen_height[index(c, r)]); };
  for (int r = 0; r < rows; ++r) {
    for (int c = 0; c < cols; ++c) {
      if (has(c, r) || raised[index(c, r)]) continue;
      int best_span = reach + 2;
      for (const auto& [dc, dr] : {std::pair<int, int>{1, 0}, {0, 1}}) {
        int a = 1, b = 1;
        while (a <= reach && !has(c - a * dc, r - a * dr)) ++a;
        while (b <= reach && !has(c + b * dc, r + b * dr)) ++b;
        // The gap between the two ground cells is a + b - 1 cells wide.
        if (a > reach || b > reach || a + b - 1 > reach || a + b >= best_span) continue;
        const std::size_t lo = index(c - a * dc, r - a * dr), hi = index(c + b * dc, r + b * dr);
        if (std::abs(seen_height[hi] - seen_height[lo]) > options.max_gap_step) continue;
        best_span = a + b;
        const double t = static_cast<double>(a) / (a + b);
        (*height)[index(c, r)] = (1.0 - t) * seen_height[lo] + t * seen_height[hi];
        (*friction)[index(c, r)] = std::min(seen_friction[lo], seen_friction[hi]);
      }
    }
  }
}

}  // namespace

void ValidateTerrainAssemblyOptions(const TerrainAssemblyOptions& o) {
  Require(o.occupied_threshold >= 0.0 && o.occupied_threshold < 1.0, "occupied_threshold", o.occupied_threshold,
          "in [0, 1)");
  Require(std::isfinite(o.max_ground_height), "max_ground_height", o.max_ground_height, "finite (world z, m)");
  Require(o.eta > 0.0 && o.eta < 1.0, "eta", o.eta, "in (0, 1)");
  Require(o.min_points >= 1 && o.min_points <= 1000000, "min_points", o.min_points, "in [1, 1000000]");
  Require(o.outlier_height >= 0.0 && o.outlier_height <= 10.0, "outlier_height", o.outlier_height,
          "in [0, 10] m (0: keep every cell)");
  Require(o.outlier_radius > 0.0 && o.outlier_radius <= 1.0, "outlier_radius", o.outlier_radius, "in (0, 1] m");
  Require(o.max_gap >= 0.0 && o.max_gap <= 10.0, "max_gap", o.max_gap, "in [0, 10] m (0: bridge no gap)");
  Require(o.max_gap_step >= 0.0 && o.max_gap_step <= 1.0, "max_gap_step", o.max_gap_step, "in [0, 1] m");
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
  // probability. Per column: the ground layer, its points' heights and summed mixtures (or, for kIndependent, the
  // product of the mixtures, rescaled whenever its largest entry falls below 1e-200 so that it cannot underflow).
  std::vector<int> ground_layer(columns, -1);
  std::vector<std::vector<float>> heights(columns);
  const bool independent = options.fusion == MaterialFusion::kIndependent;
  Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> mixture =
      Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>::Constant(
          static_cast<Eigen::Index>(columns), labels, independent ? 1.0 : 0.0);
  std::vector<int> count(columns, 0);
  // A label one point gives no mass at all still keeps this much of it: a single zero must not veto a label that
  // every other point supports.
  constexpr double kMinWeight = 1e-9;
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
        if (independent) {
          double* m = mixture.row(static_cast<Eigen::Index>(column)).data();
          double largest = 0.0;
          for (int l = 0; l < labels; ++l) {
            m[l] *= std::max(static_cast<double>(points.weights(i, l)), kMinWeight);
            largest = std::max(largest, m[l]);
          }
          if (largest < 1e-200) {
            for (int l = 0; l < labels; ++l) m[l] /= largest;
          }
        } else {
          mixture.row(static_cast<Eigen::Index>(column)) += points.weights.row(i).cast<double>();
        }
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
  std::vector<double> friction(columns, options.unknown_friction);
  Eigen::VectorXd weights(labels);
  for (std::size_t column = 0; column < columns; ++column) {
    if (std::isnan(height[column]) || count[column] < options.min_points) continue;
    weights = mixture.row(static_cast<Eigen::Index>(column)).transpose();
    const double total = weights.sum();
    if (total > 0.0) {
      weights /= total;
      friction[column] = perception::FrictionQuantile(registry, weights, options.eta, options.quantile_method);
    }
  }
  std::vector<char> raised(columns, 0);
  if (options.outlier_height > 0.0 || options.median_heights) {
    RemoveHeightOutliers(cols, rows, res, options, &height, &raised);
  }
  if (options.max_gap > 0.0) BridgeGaps(cols, rows, res, options, raised, &height, &friction);
  for (int r = 0; r < rows; ++r) {
    for (int c = 0; c < cols; ++c) {
      const std::size_t column = static_cast<std::size_t>(r) * static_cast<std::size_t>(cols) + static_cast<std::size_t>(c);
      if (std::isnan(height[column])) continue;
      const Eigen::Vector3d normal = Eigen::Vector3d(-slope(c, r, 1, 0), -slope(c, r, 0, 1), 1.0).normalized();
      terrain.SetCell(c, r, height[column], normal, friction[column]);
    }
  }

  // Everything occupied above the ground cell is an obstacle for the body, with its probability; so is the ground
  // cell of a column that lost its ground for standing above its neighbours.
  std::vector<TerrainMap::OccupiedVoxel> voxels;
  for (int r = 0; r < rows; ++r) {
    for (int c = 0; c < cols; ++c) {
      const std::size_t column = static_cast<std::size_t>(r) * static_cast<std::size_t>(cols) + static_cast<std::size_t>(c);
      for (int k = ground_layer[column] + (raised[column] ? 0 : 1); k < layers; ++k) {
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
