#pragma once

/// @file
/// GridPathPlanner: A* or Dijkstra on a traversability raster, replanned as the map changes, as a system.

#include <Eigen/Core>

#include "cairn/planning/grid/grid_search.h"
#include "cairn/systems/framework/leaf_system.h"

namespace cairn::planning {

/// Every `period` seconds (from t = 0) plans from `start` to `goal` on the traversability raster of its input
/// (GridSearch), and keeps the result as state. The map changes between plans (new observations, probes); a
/// plan whose previous path the new map blocks counts as a replan. The search is the expensive part, so it lives
/// in the update event; its expansion budget (GridSearch::Options::max_expansions) keeps results reproducible.
///
/// | port | type | meaning |
/// |---|---|---|
/// | input `traversability` | Eigen::MatrixXd | t by cell (i along x, j along y), NaN unknown (TraversabilityAnalyzer's output) |
/// | input `start` | vector of size 2 | the robot's x-y, world |
/// | input `goal` | vector of size 2 | the goal's x-y, world |
/// | output `path` | Eigen::Matrix2Xd | cell centres from start to goal (no columns when there is no path) |
/// | output `status` | vector of size 3 | [found (0/1), path cost, replans so far] |
class GridPathPlanner final : public systems::LeafSystem {
 public:
  /// The raster's placement (`resolution`, `min_corner`) is fixed: a global map. Throws std::invalid_argument for
  /// a non-positive or non-finite period or resolution, or bad search options.
  GridPathPlanner(double resolution, const Eigen::Vector2d& min_corner, const GridSearch::Options& options,
                  double period);

  const systems::InputPort& get_traversability_input_port() const { return get_input_port(0); }
  const systems::InputPort& get_start_input_port() const { return get_input_port(1); }
  const systems::InputPort& get_goal_input_port() const { return get_input_port(2); }
  const systems::OutputPort& get_path_output_port() const { return get_output_port(0); }
  const systems::OutputPort& get_status_output_port() const { return get_output_port(1); }

 private:
  struct Plan {
    GridPath path;
    int replans{0};
  };
  void Update(const systems::Context& context, systems::State* next) const;

  double resolution_;
  Eigen::Vector2d min_corner_;
  GridSearch search_;
  int plan_state_{};
};

}  // namespace cairn::planning
