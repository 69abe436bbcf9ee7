#include <cairn/planning/footstep/ara_star.h>

#include <cstdint>
#include <queue>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "expect_throws.h"

namespace cairn::planning {
namespace {

// An 8-connected grid with random cell costs and walls; the heuristic is the octile distance times the cheapest
// cell cost, which is admissible.
class GridGraph {
 public:
  using Key = std::uint64_t;
  GridGraph(int size, unsigned seed, double wall_fraction) : size_(size), cost_(size * size), wall_(size * size) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> uniform(1.0, 5.0);
    std::bernoulli_distribution wall(wall_fraction);
    for (int i = 0; i < size * size; ++i) {
      cost_[i] = uniform(rng);
      wall_[i] = wall(rng);
    }
    wall_[0] = false;
    goal_ = size * size - 1;
    wall_[goal_] = false;
  }
  double Heuristic(const Key& k) const {
    const double dx = std::abs(static_cast<int>(k % size_) - static_cast<int>(goal_ % size_));
    const double dy = std::abs(static_cast<int>(k / size_) - static_cast<int>(goal_ / size_));
    return 1.0 * (std::max(dx, dy) + (std::sqrt(2.0) - 1.0) * std::min(dx, dy));
  }
  bool IsGoal(const Key& k) const { return k == goal_; }
  template <class Emit>
  void ForEachSuccessor(const Key& k, Emit&& emit) {
    ++expansions;
    const int x = static_cast<int>(k % size_), y = static_cast<int>(k / size_);
    for (int dy = -1; dy <= 1; ++dy) {
      for (int dx = -1; dx <= 1; ++dx) {
        if (dx == 0 && dy == 0) continue;
        const int nx = x + dx, ny = y + dy;
        if (nx < 0 || ny < 0 || nx >= size_ || ny >= size_) continue;
        const Key n = static_cast<Key>(ny * size_ + nx);
        if (wall_[n]) continue;
        emit(n, cost_[n] * std::hypot(dx, dy));
      }
    }
  }
  // Dijkstra from 0, the reference.
  double OptimalCost() {
    std::vector<double> dist(size_ * size_, 1e300);
    using Item = std::pair<double, Key>;
    std::priority_queue<Item, std::vector<Item>, std::greater<Item>> queue;
    dist[0] = 0.0;
    queue.push({0.0, 0});
    while (!queue.empty()) {
      const auto [d, k] = queue.top();
      queue.pop();
      if (d > dist[k]) continue;
      ForEachSuccessor(k, [&](Key n, double c) {
        if (d + c < dist[n]) {
          dist[n] = d + c;
          queue.push({dist[n], n});
        }
      });
    }
    return dist[goal_];
  }
  void Block(int x, int y) { wall_[y * size_ + x] = true; }
  long expansions{0};

 private:
  int size_;
  std::vector<double> cost_;
  std::vector<bool> wall_;
  Key goal_;
};

double PathCost(GridGraph& graph, const std::vector<std::uint64_t>& path) {
  double cost = 0.0;
  for (std::size_t i = 1; i < path.size(); ++i) {
    double edge = -1.0;
    graph.ForEachSuccessor(path[i - 1], [&](std::uint64_t n, double c) {
      if (n == path[i]) edge = c;
    });
    EXPECT_GE(edge, 0.0) << "consecutive path states are not connected";
    cost += edge;
  }
  return cost;
}

TEST(AraStarTest, ReachesTheOptimumOfDijkstraAndPublishesDecreasingCosts) {
  for (unsigned seed : {1u, 2u, 3u}) {
    GridGraph graph(40, seed, 0.2);
    const double optimum = graph.OptimalCost();
    ASSERT_LT(optimum, 1e300);
    AraStarOptions options;
    options.initial_epsilon = 3.0;
    options.epsilon_step = 0.5;
    const auto result = AraStar(graph, {0}, options);
    ASSERT_TRUE(result.found);
    EXPECT_NEAR(result.cost, optimum, 1e-9);
    EXPECT_DOUBLE_EQ(result.bound, 1.0);
    EXPECT_NEAR(PathCost(graph, result.path), result.cost, 1e-9);
    ASSERT_FALSE(result.improvements.empty());
    for (std::size_t i = 1; i < result.improvements.size(); ++i) {
      EXPECT_LE(result.improvements[i].cost, result.improvements[i - 1].cost + 1e-12);
    }
    // Every published bound holds.
    for (const AraStarImprovement& improvement : result.improvements) {
      EXPECT_LE(improvement.cost, improvement.bound * optimum + 1e-9);
      EXPECT_LE(improvement.bound, improvement.epsilon + 1e-12);
    }
  }
}

TEST(AraStarTest, ATruncatedSearchKeepsItsBound) {
  GridGraph graph(60, 7, 0.25);
  const double optimum = graph.OptimalCost();
  AraStarOptions options;
  options.initial_epsilon = 5.0;
  options.epsilon_step = 0.2;
  options.max_expansions = 2500;
  const auto result = AraStar(graph, {0}, options);
  ASSERT_TRUE(result.found);
  EXPECT_TRUE(result.expansion_limit_reached);
  EXPECT_GE(result.cost, optimum - 1e-9);
  EXPECT_LE(result.cost, result.bound * optimum + 1e-9);
}

TEST(AraStarTest, StopsAtTheFinalEpsilon) {
  GridGraph graph(60, 3, 0.2);
  const double optimum = graph.OptimalCost();
  AraStarOptions options;
  options.initial_epsilon = 3.0;
  options.final_epsilon = 2.0;
  const auto result = AraStar(graph, {0}, options);
  ASSERT_TRUE(result.found);
  EXPECT_LE(result.bound, 2.0);
  EXPECT_LE(result.cost, 2.0 * optimum + 1e-9);
  EXPECT_GE(result.improvements.back().epsilon, 2.0);
}

TEST(AraStarTest, TerminatesWhenTheEpsilonStepIsBelowRounding) {
  GridGraph graph(30, 5, 0.2);
  AraStarOptions options;
  options.initial_epsilon = 3.0;
  options.epsilon_step = 1e-300;
  const auto result = AraStar(graph, {0}, options);
  ASSERT_TRUE(result.found);
  EXPECT_DOUBLE_EQ(result.bound, 1.0);
  EXPECT_LE(result.improvements.size(), 50u);  // each pass lowers epsilon to at most the proven bound
}

TEST(AraStarTest, IsDeterministic) {
  GridGraph a(40, 11, 0.2), b(40, 11, 0.2);
  const auto ra = AraStar(a, {0}, AraStarOptions{});
  const auto rb = AraStar(b, {0}, AraStarOptions{});
  EXPECT_EQ(ra.path, rb.path);
  EXPECT_EQ(ra.expansions, rb.expansions);
}

TEST(AraStarTest, ReportsAnUnreachableGoal) {
  GridGraph graph(10, 5, 0.0);
  for (int i = 0; i < 10; ++i) graph.Block(5, i);  // a wall across the grid
  const auto result = AraStar(graph, {0}, AraStarOptions{});
  EXPECT_FALSE(result.found);
  EXPECT_TRUE(result.exhausted);
  EXPECT_EQ(result.generated, 50);
}

TEST(AraStarTest, RejectsBadOptions) {
  GridGraph graph(4, 1, 0.0);
  AraStarOptions options;
  options.initial_epsilon = 0.5;
  CAIRN_EXPECT_THROWS_WITH(AraStar(graph, {0}, options), std::invalid_argument, "initial_epsilon must be >= 1");
  options = AraStarOptions{};
  options.epsilon_step = 0.0;
  CAIRN_EXPECT_THROWS_WITH(AraStar(graph, {0}, options), std::invalid_argument, "epsilon_step must be > 0");
  options = AraStarOptions{};
  options.final_epsilon = 4.0;
  CAIRN_EXPECT_THROWS_WITH(AraStar(graph, {0}, options), std::invalid_argument,
                           "final_epsilon must be in [1, initial_epsilon], got 4");
  options = AraStarOptions{};
  options.time_limit = -1.0;
  CAIRN_EXPECT_THROWS_WITH(AraStar(graph, {0}, options), std::invalid_argument, "time_limit must be > 0");
}

}  // namespace
}  // namespace cairn::planning
