#pragma once

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <limits>
#include <queue>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <vector>

#include <cairn/common/number_text.h>

namespace cairn::planning {

/// Settings of an Anytime Repairing A* search (Likhachev, Gordon and Thrun, NIPS 2003).
struct AraStarOptions {
  /// First inflation ε of the heuristic; the first solution costs at most ε times the optimum.
  double initial_epsilon{3.0};
  /// ε decreases by this much after every solution, down to final_epsilon.
  double epsilon_step{0.5};
  /// The search stops once it has a solution proven within this factor of the optimum (1: optimal).
  double final_epsilon{1.0};
  /// Wall-clock budget in seconds; when it runs out the best solution so far is returned with its bound.
  double time_limit{std::numeric_limits<double>::infinity()};
  /// Expansion budget (negative: unlimited). Unlike the time limit it makes truncated searches reproducible.
  std::int64_t max_expansions{-1};
};

/// One solution published by the anytime search.
struct AraStarImprovement {
  double epsilon{0.0};  ///< inflation the solution was found with
  double bound{0.0};    ///< proven suboptimality bound of the solution (cost / lower bound of the optimum)
  double cost{0.0};
  double seconds{0.0};  ///< since the start of the search
  std::int64_t expansions{0};
};

/// What an ARA* search found.
template <typename Key>
struct AraStarResult {
  bool found{false};
  std::vector<Key> path;  ///< from a start to a goal
  double cost{std::numeric_limits<double>::infinity()};
  /// Proven bound: cost <= bound * optimal cost (1: optimal).
  double bound{std::numeric_limits<double>::infinity()};
  /// The search ran out of states: no goal is reachable (only meaningful when !found).
  bool exhausted{false};
  bool time_limit_reached{false};
  bool expansion_limit_reached{false};
  std::int64_t expansions{0};
  std::int64_t generated{0};  ///< distinct states seen
  double seconds{0.0};
  std::vector<AraStarImprovement> improvements;
};

/// Anytime Repairing A*: weighted A* searches with a decreasing inflation ε that reuse each other's work, so a
/// first plan comes quickly and improves towards the optimum while time remains.
///
/// `Graph` provides
/// @code
///   using Key = ...;                          // hashable, equality-comparable state identifier
///   double Heuristic(const Key&) const;       // admissible (never overestimates) for the bound to hold
///   bool IsGoal(const Key&) const;            // goal states are not expanded
///   template <class Emit> void ForEachSuccessor(const Key&, Emit&& emit);   // emit(Key, double cost >= 0)
/// @endcode
///
/// Ties in f = g + ε h are broken by larger g (deeper first), then by discovery order, so a search is
/// deterministic for a deterministic graph (up to where a time limit stops it).
template <class Graph, class Hash = std::hash<typename Graph::Key>>
AraStarResult<typename Graph::Key> AraStar(Graph& graph, const std::vector<typename Graph::Key>& starts,
                                           const AraStarOptions& options) {
  using Key = typename Graph::Key;
  using Clock = std::chrono::steady_clock;
  if (!(options.initial_epsilon >= 1.0)) {
    throw std::invalid_argument("AraStar: initial_epsilon must be >= 1, got " + FormatShort(options.initial_epsilon));
  }
  if (!(options.epsilon_step > 0.0)) {
    throw std::invalid_argument("AraStar: epsilon_step must be > 0, got " + FormatShort(options.epsilon_step) +
                                "; use initial_epsilon = 1 for a single optimal search");
  }
  if (!(options.final_epsilon >= 1.0 && options.final_epsilon <= options.initial_epsilon)) {
    throw std::invalid_argument("AraStar: final_epsilon must be in [1, initial_epsilon], got " +
                                FormatShort(options.final_epsilon));
  }
  if (!(options.time_limit > 0.0)) {
    throw std::invalid_argument("AraStar: time_limit must be > 0 seconds, got " + FormatShort(options.time_limit));
  }

  constexpr double kInf = std::numeric_limits<double>::infinity();
  struct Node {
    Key key;
    double g;
    double h;
    double edge_cost;  // of the edge from parent
    std::int32_t parent;
    std::uint32_t closed_in;  // iteration number + 1 in which the node was expanded, 0 if never
    bool in_open;
    bool in_incons;
    bool goal;
  };
  struct Entry {
    double f;
    double g;
    std::int32_t id;
  };
  // std::priority_queue pops the largest: "less" means worse.
  struct Worse {
    bool operator()(const Entry& a, const Entry& b) const {
      if (a.f != b.f) return a.f > b.f;
      if (a.g != b.g) return a.g < b.g;
      return a.id > b.id;
    }
  };

  const Clock::time_point start_time = Clock::now();
  auto elapsed = [&] { return std::chrono::duration<double>(Clock::now() - start_time).count(); };

  AraStarResult<Key> result;
  std::vector<Node> nodes;
  std::unordered_map<Key, std::int32_t, Hash> index;
  index.reserve(1 << 16);
  nodes.reserve(1 << 16);
  std::priority_queue<Entry, std::vector<Entry>, Worse> open;
  std::vector<std::int32_t> incons;
  double epsilon = options.initial_epsilon;
  std::uint32_t iteration = 0;
  std::int32_t best_goal = -1;

  auto node_of = [&](const Key& key) -> std::int32_t {
    auto [it, inserted] = index.try_emplace(key, static_cast<std::int32_t>(nodes.size()));
    if (inserted) {
      const bool goal = graph.IsGoal(key);
      nodes.push_back(Node{key, kInf, goal ? 0.0 : graph.Heuristic(key), 0.0, -1, 0, false, false, goal});
    }
    return it->second;
  };
  auto push = [&](std::int32_t id) {
    Node& n = nodes[id];
    n.in_open = true;
    open.push(Entry{n.g + epsilon * n.h, n.g, id});
  };
  auto best_goal_cost = [&] { return best_goal < 0 ? kInf : nodes[best_goal].g; };
  // ARA*'s bound: the optimum is at least min over OPEN and INCONS of g + h.
  auto lower_bound = [&] {
    double lb = kInf;
    for (const Node& n : nodes) {
      if (n.in_open || n.in_incons) lb = std::min(lb, n.g + n.h);
    }
    return lb;
  };
  // `completed`: ImprovePath finished under the current ε, so the solution is within ε of the optimum; otherwise
  // (stopped by a limit) only the OPEN/INCONS lower bound and earlier completed bounds hold.
  auto publish = [&](bool completed) {
    std::vector<Key> path;
    double cost = 0.0;
    for (std::int32_t id = best_goal; id >= 0; id = nodes[id].parent) {
      path.push_back(nodes[id].key);
      cost += nodes[id].edge_cost;
    }
    std::reverse(path.begin(), path.end());
    const double lb = lower_bound();
    double bound = lb >= cost ? 1.0 : (lb > 0.0 ? cost / lb : kInf);
    if (completed) bound = std::min(bound, epsilon);
    if (result.found) bound = std::min(bound, result.bound);  // earlier bounds hold for any cheaper path
    if (!result.found || cost < result.cost) {
      result.path = std::move(path);
      result.cost = cost;
    }
    result.found = true;
    result.bound = std::max(1.0, bound);
    result.improvements.push_back(AraStarImprovement{epsilon, result.bound, result.cost, elapsed(), result.expansions});
  };

  for (const Key& key : starts) {
    const std::int32_t id = node_of(key);
    nodes[id].g = 0.0;
    if (nodes[id].goal) best_goal = id;
  }
  for (std::int32_t id = 0; id < static_cast<std::int32_t>(nodes.size()); ++id) push(id);

  bool stop = false;
  while (!stop) {
    // ImprovePath: expand while some OPEN state could still lead to a cheaper goal under the current ε.
    while (!open.empty()) {
      const Entry top = open.top();
      Node& n = nodes[top.id];
      if (!n.in_open || top.g != n.g) {  // stale entry
        open.pop();
        continue;
      }
      if (best_goal_cost() <= top.f) break;
      // Every expansion: one can take long (thousands of successors, each checked against every obstacle).
      if (elapsed() > options.time_limit) {
        result.time_limit_reached = true;
        stop = true;
        break;
      }
      if (options.max_expansions >= 0 && result.expansions >= options.max_expansions) {
        result.expansion_limit_reached = true;
        stop = true;
        break;
      }
      open.pop();
      n.in_open = false;
      n.closed_in = iteration + 1;
      ++result.expansions;
      if (n.goal) continue;
      const double g = n.g;
      const std::int32_t parent = top.id;
      const Key expanded = nodes[parent].key;  // a copy: emitting successors may reallocate `nodes`
      graph.ForEachSuccessor(expanded, [&](const Key& key, double cost) {
        const std::int32_t id = node_of(key);
        Node& s = nodes[id];
        const double candidate = g + cost;
        if (!(candidate < s.g)) return;
        s.g = candidate;
        s.parent = parent;
        s.edge_cost = cost;
        if (s.goal && candidate < best_goal_cost()) best_goal = id;
        if (s.closed_in == iteration + 1) {
          if (!s.in_incons) {
            s.in_incons = true;
            incons.push_back(id);
          }
        } else {
          push(id);
        }
      });
    }
    if (best_goal >= 0) publish(!stop);
    if (stop) break;
    if (best_goal < 0) {  // OPEN ran dry without reaching a goal
      result.exhausted = true;
      break;
    }
    if (epsilon <= options.final_epsilon || result.bound <= options.final_epsilon) break;
    if (elapsed() > options.time_limit) {
      result.time_limit_reached = true;
      break;
    }
    // Next ε: move INCONS into OPEN and re-key everything. ε must fall at every pass (a step below the
    // floating-point resolution of ε would otherwise repeat the same pass forever).
    const double next = std::max(options.final_epsilon, std::min(epsilon - options.epsilon_step, result.bound));
    epsilon = next < epsilon ? next : options.final_epsilon;
    ++iteration;
    for (std::int32_t id : incons) {
      nodes[id].in_incons = false;
      nodes[id].in_open = true;
    }
    incons.clear();
    open = {};
    for (std::int32_t id = 0; id < static_cast<std::int32_t>(nodes.size()); ++id) {
      if (nodes[id].in_open) push(id);
    }
  }
  result.generated = static_cast<std::int64_t>(nodes.size());
  result.seconds = elapsed();
  return result;
}

}  // namespace cairn::planning
