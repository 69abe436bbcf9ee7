#include "cairn/planning/grid/grid_search.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <queue>
#include <stdexcept>
#include <utility>

#include "cairn/common/number_text.h"

namespace cairn::planning {

namespace {

constexpr int kDi[8] = {1, -1, 0, 0, 1, 1, -1, -1};
constexpr int kDj[8] = {0, 0, 1, -1, 1, -1, 1, -1};

std::string CellText(const Eigen::Vector2i& c) { return "(" + FormatShort(c.x()) + ", " + FormatShort(c.y()) + ")"; }

}  // namespace

GridSearch::GridSearch(const Options& options) : options_(options) {
  if (!(options.blocked_below >= 0.0 && options.blocked_below <= 1.0)) {
    throw std::invalid_argument("GridSearch: blocked_below " + FormatShort(options.blocked_below) +
                                " must be in [0, 1] (e.g. 0.1)");
  }
  if (!(options.unknown_traversability > 0.0 && options.unknown_traversability <= 1.0)) {
    throw std::invalid_argument("GridSearch: unknown_traversability " + FormatShort(options.unknown_traversability) +
                                " must be in (0, 1] (1 plans optimistically through unseen ground)");
  }
}

double GridSearch::Value(const TraversabilityGrid& grid, const Eigen::Vector2i& cell) const {
  const double t = grid.values(cell.x(), cell.y());
  return std::isnan(t) ? options_.unknown_traversability : t;
}

bool GridSearch::Passable(const TraversabilityGrid& grid, const Eigen::Vector2i& cell) const {
  if (!grid.Contains(cell)) return false;
  const double t = Value(grid, cell);
  return t > 0.0 && t >= options_.blocked_below;
}

double GridSearch::EdgeCost(const TraversabilityGrid& grid, const Eigen::Vector2i& a, const Eigen::Vector2i& b) const {
  const Eigen::Vector2i d = b - a;
  const double length = (d.x() != 0 && d.y() != 0 ? std::sqrt(2.0) : 1.0) * grid.resolution;
  return length * 0.5 * (1.0 / Value(grid, a) + 1.0 / Value(grid, b));
}

GridPath GridSearch::Plan(const TraversabilityGrid& grid, const Eigen::Vector2i& start,
                          const Eigen::Vector2i& goal) const {
  grid.Validate();
  if (!grid.Contains(start) || !grid.Contains(goal)) {
    throw std::invalid_argument("GridSearch: start " + CellText(start) + " or goal " + CellText(goal) +
                                " is outside the " + FormatShort(grid.rows()) + " x " + FormatShort(grid.cols()) +
                                " grid");
  }
  GridPath result;
  if (!Passable(grid, start) || !Passable(grid, goal)) return result;
  const int rows = grid.rows();
  const int cols = grid.cols();
  const int n = rows * cols;
  const std::int64_t budget = options_.max_expansions < 0 ? n : options_.max_expansions;
  std::vector<double> g(n, std::numeric_limits<double>::infinity());
  std::vector<int> parent(n, -1);
  std::vector<char> closed(n, 0);
  const auto index = [cols](const Eigen::Vector2i& c) { return c.x() * cols + c.y(); };
  const bool astar = options_.algorithm == Algorithm::kAStar;
  const auto heuristic = [&](const Eigen::Vector2i& c) {
    if (!astar) return 0.0;
    const double dx = std::abs(c.x() - goal.x());
    const double dy = std::abs(c.y() - goal.y());
    return grid.resolution * ((std::sqrt(2.0) - 1.0) * std::min(dx, dy) + std::max(dx, dy));
  };
  using Entry = std::pair<double, int>;  // (f, index): ties by the lower index
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> open;
  const int s = index(start);
  const int t = index(goal);
  g[s] = 0.0;
  open.emplace(heuristic(start), s);
  while (!open.empty()) {
    const auto [f, u] = open.top();
    open.pop();
    if (closed[u]) continue;
    if (u == t) break;
    if (result.expansions >= budget) {
      result.expansion_limit_reached = true;
      return result;
    }
    closed[u] = 1;
    ++result.expansions;
    const Eigen::Vector2i cu(u / cols, u % cols);
    for (int k = 0; k < 8; ++k) {
      const Eigen::Vector2i cv(cu.x() + kDi[k], cu.y() + kDj[k]);
      if (!Passable(grid, cv)) continue;
      if (k >= 4 && (!Passable(grid, Eigen::Vector2i(cu.x() + kDi[k], cu.y())) ||
                     !Passable(grid, Eigen::Vector2i(cu.x(), cu.y() + kDj[k])))) {
        continue;  // no corner cutting
      }
      const int v = index(cv);
      if (closed[v]) continue;
      const double candidate = g[u] + EdgeCost(grid, cu, cv);
      if (candidate < g[v]) {
        g[v] = candidate;
        parent[v] = u;
        open.emplace(candidate + heuristic(cv), v);
      }
    }
  }
  if (!std::isfinite(g[t])) return result;
  result.found = true;
  result.cost = g[t];
  for (int v = t; v != -1; v = parent[v]) result.cells.emplace_back(v / cols, v % cols);
  std::reverse(result.cells.begin(), result.cells.end());
  for (std::size_t k = 1; k < result.cells.size(); ++k) {
    result.length += (result.cells[k] - result.cells[k - 1]).cast<double>().norm() * grid.resolution;
  }
  return result;
}

double GridSearch::PathCost(const TraversabilityGrid& grid, const std::vector<Eigen::Vector2i>& cells) const {
  const double inf = std::numeric_limits<double>::infinity();
  if (cells.empty()) return inf;
  if (!Passable(grid, cells.front())) return inf;
  double cost = 0.0;
  for (std::size_t k = 1; k < cells.size(); ++k) {
    const Eigen::Vector2i d = cells[k] - cells[k - 1];
    if (d.cwiseAbs().maxCoeff() != 1 || !Passable(grid, cells[k])) return inf;
    if (d.x() != 0 && d.y() != 0 &&
        (!Passable(grid, Eigen::Vector2i(cells[k - 1].x() + d.x(), cells[k - 1].y())) ||
         !Passable(grid, Eigen::Vector2i(cells[k - 1].x(), cells[k - 1].y() + d.y())))) {
      return inf;
    }
    cost += EdgeCost(grid, cells[k - 1], cells[k]);
  }
  return cost;
}

}  // namespace cairn::planning
