#pragma once

/// @file
/// GridSearch: Dijkstra and A* on a traversability grid (seed 001 §6 plans with Dijkstra).

#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "cairn/planning/grid/traversability_grid.h"

namespace cairn::planning {

/// What a grid search found.
struct GridPath {
  bool found{false};
  /// Cells from start to goal (8-connected neighbours).
  std::vector<Eigen::Vector2i> cells;
  /// Sum of the edge costs (see GridSearch).
  double cost{std::numeric_limits<double>::infinity()};
  /// Length in metres.
  double length{0.0};
  std::int64_t expansions{0};
  /// The expansion budget ran out before the goal was settled.
  bool expansion_limit_reached{false};
};

/// Shortest paths on a TraversabilityGrid, 8-connected. Moving from cell a to neighbour b costs
///   d(a, b) · (1 / t_a + 1 / t_b) / 2,
/// d being the centre distance (resolution or √2 · resolution): a fully traversable cell costs its length, a
/// semi-traversable one more, in inverse proportion to t. Cells with t below `blocked_below` are untraversable
/// (never entered); unknown cells (NaN) count as `unknown_traversability`. Diagonal moves may not cut the corner
/// of a blocked cell. A* uses the octile distance, admissible and consistent since every cell costs at least its
/// length, so both algorithms return the same optimal cost. Ties break by cell index: results are reproducible.
class GridSearch {
 public:
  enum class Algorithm { kDijkstra, kAStar };

  struct Options {
    Algorithm algorithm{Algorithm::kAStar};
    /// Cells with a traversability below this are blocked (seed 001: 0 is untraversable; 0.1 also blocks ground
    /// that held less than a tenth of the hard-ground probe force).
    double blocked_below{0.1};
    /// Traversability assumed for unknown cells (optimistic by default: unseen ground is explored).
    double unknown_traversability{1.0};
    /// Expansion budget (negative: the number of cells, i.e. unlimited).
    std::int64_t max_expansions{-1};
  };

  /// Throws std::invalid_argument for blocked_below outside [0, 1] or an unknown traversability outside
  /// (0, 1].
  explicit GridSearch(const Options& options);
  GridSearch() : GridSearch(Options{}) {}

  const Options& options() const { return options_; }

  /// Whether a cell can be entered.
  bool Passable(const TraversabilityGrid& grid, const Eigen::Vector2i& cell) const;

  /// The optimal path from `start` to `goal` (cells). Throws std::invalid_argument for a grid that fails
  /// Validate() or a start or goal outside the grid. A blocked start or goal, or no connection, gives found =
  /// false.
  GridPath Plan(const TraversabilityGrid& grid, const Eigen::Vector2i& start, const Eigen::Vector2i& goal) const;

  /// The cost of an existing path on (a possibly changed) grid: infinity if it enters a blocked cell or a step is
  /// not between neighbours. Replanning compares this with a fresh plan when the map changes.
  double PathCost(const TraversabilityGrid& grid, const std::vector<Eigen::Vector2i>& cells) const;

  /// The cost of one move between neighbouring passable cells.
  double EdgeCost(const TraversabilityGrid& grid, const Eigen::Vector2i& a, const Eigen::Vector2i& b) const;

 private:
  double Value(const TraversabilityGrid& grid, const Eigen::Vector2i& cell) const;

  Options options_;
};

}  // namespace cairn::planning
