#include <cairn/planning/footstep/plan_footsteps.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iomanip>
#include <limits>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <utility>

#include <cairn/common/number_text.h>
#include <cairn/planning/footstep/ara_star.h>
#include <cairn/planning/footstep/internal/plan_on_stance_graph.h>
#include <cairn/planning/footstep/stance_graph.h>
#include <cairn/planning/footstep/time_limit_reached.h>

namespace cairn::planning {
namespace {

std::string DescribeFoot(const char* what, FootSide side, const FootPose& pose) {
  std::ostringstream out;
  out << std::fixed << std::setprecision(2) << what << " " << FootSideName(side) << " foot at (" << pose.x << ", "
      << pose.y << ")";
  return out.str();
}

// Why the foothold under `pose` cannot carry a foot, or "" when it can.
std::string CheckFoothold(StanceGraph& graph, const TerrainMap& terrain, const char* what, FootSide side,
                          const FootPose& pose, StanceGraph::LatticeFoot* foot) {
  if (!graph.Snap(pose, foot)) {
    return DescribeFoot(what, side, pose) + " lies outside the terrain map";
  }
  if (!graph.EvaluateFoothold(*foot).supported) {
    int col, row;
    std::string detail = "its sole lacks flat, walkable ground";
    if (terrain.CellAt(pose.x, pose.y, &col, &row) && terrain.has_ground(col, row) &&
        terrain.friction(col, row) <= 0.0) {
      detail = "the ground there is not walkable (friction 0)";
    }
    return DescribeFoot(what, side, pose) + " is not supported: " + detail;
  }
  return "";
}

// Why no foothold within `goal`'s tolerances of its `side` foot can carry a foot, or "" when one can: the search
// ends at any stance within the tolerances (StanceGraph::IsGoal), so an unsupported goal foothold only matters when
// every lattice foothold around it is unsupported too (perceived terrain rarely supports the exact goal pose).
std::string CheckGoalFoothold(StanceGraph& graph, const TerrainMap& terrain, FootSide side, const StanceGoal& goal,
                              const FootstepPlannerOptions& options) {
  const FootPose& pose = side == FootSide::kLeft ? goal.stance.left : goal.stance.right;
  StanceGraph::LatticeFoot foot;
  const std::string exact = CheckFoothold(graph, terrain, "goal", side, pose, &foot);
  if (exact.empty() || !graph.Snap(pose, &foot)) return exact;
  // The lattice feet around the snapped one, one step further than the tolerances (rounding), each kept if it lies
  // within them as StanceGraph::IsGoal judges. Candidates are poses snapped back onto the lattice, so none lies
  // outside it; a tolerance wider than the map is bounded by the map.
  const double step = options.lattice_resolution, turn = 2.0 * M_PI / options.orientations;
  const double cells = std::ceil(std::hypot(terrain.max_corner().x() - terrain.min_corner().x(),
                                            terrain.max_corner().y() - terrain.min_corner().y()) / step);
  const int reach = static_cast<int>(std::min(std::ceil(goal.position_tolerance / step), cells)) + 1;
  const int turns = std::min(static_cast<int>(std::min(std::ceil(goal.yaw_tolerance / turn), 1e6)) + 1,
                             options.orientations / 2);
  const FootPose centre = graph.PoseOf(foot);
  for (int dy = -reach; dy <= reach; ++dy) {
    for (int dx = -reach; dx <= reach; ++dx) {
      for (int dt = -turns; dt <= turns; ++dt) {
        FootPose candidate = centre;
        candidate.x += dx * step;
        candidate.y += dy * step;
        candidate.theta += dt * turn;
        StanceGraph::LatticeFoot near;
        if (!graph.Snap(candidate, &near)) continue;
        const FootPose at = graph.PoseOf(near);
        if (std::hypot(at.x - pose.x, at.y - pose.y) > goal.position_tolerance ||
            std::abs(std::remainder(at.theta - pose.theta, 2.0 * M_PI)) > goal.yaw_tolerance) {
          continue;
        }
        if (graph.EvaluateFoothold(near).supported) return "";
      }
    }
  }
  std::ostringstream reason;
  reason << exact << ", nor is any foothold within the goal's tolerance (" << std::setprecision(3)
         << goal.position_tolerance << " m, " << goal.yaw_tolerance
         << " rad); move the goal or widen its tolerance";
  return reason.str();
}

using Clock = std::chrono::steady_clock;

// Seconds left before `deadline` (infinity without one), at least a nanosecond so that AraStar accepts it and
// stops at its first check.
double SecondsLeft(Clock::time_point deadline) {
  if (deadline == Clock::time_point::max()) return std::numeric_limits<double>::infinity();
  return std::max(1e-9, std::chrono::duration<double>(deadline - Clock::now()).count());
}

// The search found no plan although it was not stopped: tell "every way needs more friction" from "no way at
// all" by planning again with friction ignored, within what is left of the time limit. What the second search met
// is what "no way at all" is made of, so its counts are the ones reported (the first may have expanded nothing:
// with friction, no start's heuristic was finite).
std::string Diagnose(StanceGraph& graph, const std::vector<StanceGraph::Key>& starts, const FootstepPlannerOptions& options,
                     const StepCostModel& cost_model, Clock::time_point deadline) {
  std::ostringstream reason;
  try {
    graph.set_ignore_friction(true, deadline);
  } catch (const TimeLimitReached&) {
    return "no plan: the search found none, and the time limit ran out before it could tell whether friction or "
           "the terrain's shape blocks the way";
  }
  if (std::none_of(starts.begin(), starts.end(), [&](StanceGraph::Key k) { return std::isfinite(graph.Heuristic(k)); })) {
    const StepReach& r = cost_model.reach();
    reason << "the goal is unreachable: no chain of supported footholds, each within one step ("
           << std::setprecision(3)
           << std::hypot(std::max(std::abs(r.dx_min), std::abs(r.dx_max)), std::max(std::abs(r.dy_min), std::abs(r.dy_max)))
           << " m) of the last and clear of obstacles, connects the start to the goal";
    return reason.str();
  }
  const FootstepPlanStatistics before = graph.rejections();
  AraStarOptions relaxed = options.search;
  relaxed.initial_epsilon = std::max(relaxed.initial_epsilon, 3.0);
  relaxed.final_epsilon = relaxed.initial_epsilon;  // the first plan answers the question
  relaxed.time_limit = SecondsLeft(deadline);
  const AraStarResult<StanceGraph::Key> frictionless = AraStar(graph, starts, relaxed);
  if (frictionless.found) {
    double needed = 0.0;
    for (std::size_t k = 1; k < frictionless.path.size(); ++k) {
      needed = std::max(needed, graph.Transition(frictionless.path[k - 1], frictionless.path[k]).transition.rcof);
    }
    reason << std::setprecision(3) << "every way to the goal needs more friction than the terrain offers (a path "
           << "ignoring friction needs an RCOF of " << needed << "); lower eta to accept more risk or choose another goal";
  } else if (frictionless.exhausted) {
    reason << "the goal is unreachable: no sequence of supported, collision-free steps leads there (with friction "
           << "ignored, " << frictionless.expansions << " stances expanded, "
           << graph.rejections().rejected_support - before.rejected_support << " footholds without support, "
           << graph.rejections().rejected_collision - before.rejected_collision << " stances in collision)";
  } else {
    reason << "no plan: the search found none, and within the budget it could not tell whether friction or the "
              "terrain's shape blocks the way";
  }
  return reason.str();
}

}  // namespace

namespace internal {

Clock::time_point CheckPlanInputs(const Stance& start, const StanceGoal& goal, const FootstepPlannerOptions& options,
                                  Clock::time_point t0) {
  for (const auto& [stance, what] : {std::pair<const Stance*, const char*>{&start, "start"}, {&goal.stance, "goal"}}) {
    const std::string problem = StanceGeometryProblem(*stance);
    if (!problem.empty()) throw std::invalid_argument(std::string("PlanFootsteps: the ") + what + " stance: " + problem);
  }
  if (!(options.search.time_limit > 0.0)) {
    throw std::invalid_argument("PlanFootsteps: time_limit must be > 0 seconds, got " +
                                FormatShort(options.search.time_limit));
  }
  // The time limit covers the whole call: the heuristic's precomputation, the search and the diagnosis after a
  // failed search. Beyond 1e9 s it is as good as none (and would overflow the clock).
  return options.search.time_limit > 1e9
             ? Clock::time_point::max()
             : t0 + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(options.search.time_limit));
}

std::string TimeLimitDuringPrecomputation(const FootstepPlannerOptions& options, const TimeLimitReached& error) {
  return "no plan within the time limit of " + FormatShort(options.search.time_limit) + " s: " + error.what() +
         "; raise the limit, crop the terrain to the region around start and goal, or coarsen the lattice";
}

FootstepPlan PlanOnStanceGraph(StanceGraph& graph, const TerrainMap& terrain, const Stance& start,
                               const StanceGoal& goal, const StepCostModel& cost_model,
                               const FootstepPlannerOptions& options, Clock::time_point t0,
                               Clock::time_point deadline) {
  auto seconds = [&] { return std::chrono::duration<double>(Clock::now() - t0).count(); };
  FootstepPlan plan;
  plan.cost_model = cost_model.description();
  plan.start = start;
  StanceGraph::LatticeFoot left, right;
  for (const std::string& reason :
       {CheckFoothold(graph, terrain, "start", FootSide::kLeft, start.left, &left),
        CheckFoothold(graph, terrain, "start", FootSide::kRight, start.right, &right),
        CheckGoalFoothold(graph, terrain, FootSide::kLeft, goal, options),
        CheckGoalFoothold(graph, terrain, FootSide::kRight, goal, options)}) {
    if (!reason.empty()) {
      plan.reason = reason;
      plan.statistics.plan_seconds = seconds();
      return plan;
    }
  }
  plan.start.left = graph.PoseOf(left);
  plan.start.right = graph.PoseOf(right);

  // Either foot may move first: the stance where the left foot landed last lets the right foot move, and vice versa.
  const std::vector<StanceGraph::Key> starts = {graph.MakeKey(right, left, FootSide::kLeft),
                                                graph.MakeKey(left, right, FootSide::kRight)};
  // The graph may have served earlier searches (FootstepReplanner): count this search's rejections only.
  const FootstepPlanStatistics before = graph.rejections();
  AraStarOptions search = options.search;
  search.time_limit = SecondsLeft(deadline);
  const AraStarResult<StanceGraph::Key> result = AraStar(graph, starts, search);
  plan.statistics.expansions = result.expansions;
  plan.statistics.generated = result.generated;
  plan.statistics.improvements = static_cast<int>(result.improvements.size());
  plan.statistics.rejected_support = graph.rejections().rejected_support - before.rejected_support;
  plan.statistics.rejected_collision = graph.rejections().rejected_collision - before.rejected_collision;
  plan.statistics.rejected_friction = graph.rejections().rejected_friction - before.rejected_friction;

  if (result.found) {
    plan.found = true;
    plan.statistics.first_plan_seconds = result.improvements.front().seconds;
    plan.statistics.epsilon = result.bound;
    for (std::size_t k = 1; k < result.path.size(); ++k) {
      plan.steps.push_back(graph.Transition(result.path[k - 1], result.path[k]));
    }
    plan.first_side = plan.steps.empty() ? FootSide::kLeft : plan.steps.front().side;
    plan.UpdateTotals();
    plan.statistics.plan_seconds = seconds();
    return plan;
  }

  std::ostringstream reason;
  if (result.time_limit_reached || result.expansion_limit_reached) {
    reason << "no plan within the search budget (" << (result.time_limit_reached ? "time limit " : "expansion limit ")
           << (result.time_limit_reached ? options.search.time_limit : static_cast<double>(options.search.max_expansions))
           << (result.time_limit_reached ? " s" : "") << ", " << result.expansions
           << " stances expanded); raise the limit or start with a larger initial epsilon";
  } else {
    reason << Diagnose(graph, starts, options, cost_model, deadline);
  }
  plan.reason = reason.str();
  plan.statistics.plan_seconds = seconds();
  return plan;
}

}  // namespace internal

FootstepPlan PlanFootsteps(const TerrainMap& terrain, const Stance& start, const StanceGoal& goal,
                           const StepCostModel& cost_model, const BipedGeometry& geometry,
                           const FootstepPlannerOptions& options) {
  const auto t0 = Clock::now();
  const Clock::time_point deadline = internal::CheckPlanInputs(start, goal, options, t0);
  std::optional<StanceGraph> graph;
  try {
    graph.emplace(terrain, cost_model, geometry, options, goal, deadline);
  } catch (const TimeLimitReached& error) {
    FootstepPlan plan;
    plan.cost_model = cost_model.description();
    plan.start = start;
    plan.reason = internal::TimeLimitDuringPrecomputation(options, error);
    plan.statistics.plan_seconds = std::chrono::duration<double>(Clock::now() - t0).count();
    return plan;
  }
  return internal::PlanOnStanceGraph(*graph, terrain, start, goal, cost_model, options, t0, deadline);
}

}  // namespace cairn::planning
