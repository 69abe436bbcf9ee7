#include "cairn/planning/grid/grid_search.h"

#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "expect_throws.h"

namespace cairn::planning {
namespace {

TraversabilityGrid RandomGrid(std::mt19937& rng, int rows, int cols) {
  TraversabilityGrid grid;
  grid.resolution = 0.1;
  grid.values.resize(rows, cols);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int i = 0; i < rows; ++i) {
    for (int j = 0; j < cols; ++j) {
      const double r = u(rng);
      grid.values(i, j) = r < 0.2 ? 0.0 : (r < 0.3 ? NAN : u(rng));
    }
  }
  return grid;
}

// An independent reference: Bellman-Ford relaxation of every edge until nothing changes.
double BruteForceCost(const GridSearch& search, const TraversabilityGrid& grid, const Eigen::Vector2i& start,
                      const Eigen::Vector2i& goal) {
  const double inf = std::numeric_limits<double>::infinity();
  if (!search.Passable(grid, start) || !search.Passable(grid, goal)) return inf;
  Eigen::MatrixXd d = Eigen::MatrixXd::Constant(grid.rows(), grid.cols(), inf);
  d(start.x(), start.y()) = 0.0;
  for (bool changed = true; changed;) {
    changed = false;
    for (int i = 0; i < grid.rows(); ++i) {
      for (int j = 0; j < grid.cols(); ++j) {
        const Eigen::Vector2i a(i, j);
        if (!std::isfinite(d(i, j))) continue;
        for (int di = -1; di <= 1; ++di) {
          for (int dj = -1; dj <= 1; ++dj) {
            const Eigen::Vector2i b(i + di, j + dj);
            if ((di == 0 && dj == 0) || !search.Passable(grid, b)) continue;
            if (di != 0 && dj != 0 &&
                (!search.Passable(grid, Eigen::Vector2i(i + di, j)) || !search.Passable(grid, Eigen::Vector2i(i, j + dj)))) {
              continue;
            }
            const double c = d(i, j) + search.EdgeCost(grid, a, b);
            if (c < d(b.x(), b.y()) - 1e-12) {
              d(b.x(), b.y()) = c;
              changed = true;
            }
          }
        }
      }
    }
  }
  return d(goal.x(), goal.y());
}

TEST(GridSearchTest, DijkstraAndAStarAreOptimalAgainstBruteForce) {
  std::mt19937 rng(42);
  int found = 0;
  for (int trial = 0; trial < 60; ++trial) {
    const TraversabilityGrid grid = RandomGrid(rng, 6 + trial % 5, 5 + trial % 7);
    std::uniform_int_distribution<int> ri(0, grid.rows() - 1), rj(0, grid.cols() - 1);
    const Eigen::Vector2i start(ri(rng), rj(rng)), goal(ri(rng), rj(rng));
    GridSearch::Options dijkstra_options;
    dijkstra_options.algorithm = GridSearch::Algorithm::kDijkstra;
    const GridSearch dijkstra(dijkstra_options), astar;
    const double reference = BruteForceCost(astar, grid, start, goal);
    const GridPath a = dijkstra.Plan(grid, start, goal);
    const GridPath b = astar.Plan(grid, start, goal);
    ASSERT_EQ(a.found, std::isfinite(reference)) << trial;
    ASSERT_EQ(b.found, std::isfinite(reference)) << trial;
    if (!a.found) continue;
    ++found;
    EXPECT_NEAR(a.cost, reference, 1e-9) << trial;
    EXPECT_NEAR(b.cost, reference, 1e-9) << trial;
    EXPECT_NEAR(astar.PathCost(grid, b.cells), b.cost, 1e-9);  // the path really costs what it says
    EXPECT_EQ(b.cells.front(), start);
    EXPECT_EQ(b.cells.back(), goal);
    EXPECT_LE(b.expansions, a.expansions);
  }
  EXPECT_GT(found, 20);  // the random grids exercise real paths, not only disconnected ones
}

TEST(GridSearchTest, PrefersTraversableDetoursAndAvoidsBlockedCells) {
  TraversabilityGrid grid;
  grid.resolution = 1.0;
  grid.values = Eigen::MatrixXd::Ones(5, 3);
  grid.values.row(2) << 0.2, 0.05, 1.0;  // the straight line crosses a cell below blocked_below
  const GridSearch search;
  const GridPath path = search.Plan(grid, Eigen::Vector2i(0, 1), Eigen::Vector2i(4, 1));
  ASSERT_TRUE(path.found);
  for (const auto& c : path.cells) EXPECT_NE(c, Eigen::Vector2i(2, 1));
  EXPECT_EQ(path.cells[2], Eigen::Vector2i(2, 2));
  // Replanning on a changed map: the old path becomes blocked, its cost infinite, and the new plan goes left.
  grid.values(2, 2) = 0.0;
  EXPECT_TRUE(std::isinf(search.PathCost(grid, path.cells)));
  const GridPath replanned = search.Plan(grid, Eigen::Vector2i(0, 1), Eigen::Vector2i(4, 1));
  ASSERT_TRUE(replanned.found);
  EXPECT_EQ(replanned.cells[2], Eigen::Vector2i(2, 0));
  EXPECT_NEAR(replanned.cost, search.PathCost(grid, replanned.cells), 1e-12);
  grid.values(2, 0) = 0.0;
  EXPECT_FALSE(search.Plan(grid, Eigen::Vector2i(0, 1), Eigen::Vector2i(4, 1)).found);
}

TEST(GridSearchTest, RejectsBadInput) {
  TraversabilityGrid grid;
  grid.values = Eigen::MatrixXd::Ones(3, 3);
  const GridSearch search;
  CAIRN_EXPECT_THROWS_WITH(search.Plan(grid, Eigen::Vector2i(0, 0), Eigen::Vector2i(3, 0)), std::invalid_argument,
                           "goal (3, 0) is outside the 3 x 3 grid");
  grid.values(1, 2) = 1.5;
  CAIRN_EXPECT_THROWS_WITH(search.Plan(grid, Eigen::Vector2i(0, 0), Eigen::Vector2i(2, 0)), std::invalid_argument,
                           "traversability 1.5 at cell (1, 2)");
  GridSearch::Options o;
  o.unknown_traversability = 0.0;
  CAIRN_EXPECT_THROWS_WITH(GridSearch{o}, std::invalid_argument, "unknown_traversability 0");
}

TEST(GridSearchTest, ExpansionBudgetIsReported) {
  TraversabilityGrid grid;
  grid.values = Eigen::MatrixXd::Ones(30, 30);
  GridSearch::Options o;
  o.max_expansions = 5;
  const GridPath path = GridSearch(o).Plan(grid, Eigen::Vector2i(0, 0), Eigen::Vector2i(29, 29));
  EXPECT_FALSE(path.found);
  EXPECT_TRUE(path.expansion_limit_reached);
  EXPECT_EQ(path.expansions, 5);
}

}  // namespace
}  // namespace cairn::planning
