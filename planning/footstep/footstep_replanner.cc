#include <cairn/planning/footstep/footstep_replanner.h>

#include <algorithm>
#include <chrono>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>

#include <cairn/planning/footstep/internal/plan_on_stance_graph.h>
#include <cairn/planning/footstep/time_limit_reached.h>

namespace cairn::planning {

FootstepReplanner::FootstepReplanner(const TerrainMap& terrain, const StanceGoal& goal,
                                     std::shared_ptr<const StepCostModel> cost_model, const BipedGeometry& geometry,
                                     const FootstepPlannerOptions& options)
    : terrain_(terrain), goal_(goal), cost_model_(std::move(cost_model)), geometry_(geometry), options_(options) {
  if (cost_model_ == nullptr) {
    throw std::invalid_argument("FootstepReplanner: the step cost model is null; pass e.g. a TransitionOracle");
  }
  const std::string problem = StanceGeometryProblem(goal.stance);
  if (!problem.empty()) throw std::invalid_argument("FootstepReplanner: the goal stance: " + problem);
  internal::CheckPlanInputs(goal.stance, goal, options, internal::Clock::now());  // the time limit
}

namespace {

bool SameObstacle(const TerrainMap::Obstacle& a, const TerrainMap::Obstacle& b) {
  return a.center == b.center && a.half_extents == b.half_extents && a.yaw == b.yaw;
}

}  // namespace

bool FootstepReplanner::UpdateTerrain(const TerrainMap& terrain) {
  if (terrain.cols() != terrain_.cols() || terrain.rows() != terrain_.rows() ||
      terrain.resolution() != terrain_.resolution() || terrain.origin() != terrain_.origin()) {
    std::ostringstream message;
    message << "FootstepReplanner::UpdateTerrain: the new terrain's grid (" << terrain.cols() << " x "
            << terrain.rows() << " cells of " << terrain.resolution() << " m) differs from the planner's ("
            << terrain_.cols() << " x " << terrain_.rows() << " of " << terrain_.resolution()
            << " m, same origin required); make a new FootstepReplanner";
    throw std::invalid_argument(message.str());
  }
  // Cost-raising only: old obstacles kept (new ones may follow), and every cell keeps its ground (same height
  // and normal) with no more friction, or loses its ground or walkability.
  bool raises_only = terrain.obstacles().size() >= terrain_.obstacles().size();
  // Voxels shape the heuristic too (those that alone block a body): any change to them rebuilds it.
  raises_only = raises_only && terrain.voxel_size() == terrain_.voxel_size() &&
                terrain.occupied_voxels().size() == terrain_.occupied_voxels().size();
  for (std::size_t k = 0; raises_only && k < terrain.occupied_voxels().size(); ++k) {
    raises_only = terrain.occupied_voxels()[k].center == terrain_.occupied_voxels()[k].center &&
                  terrain.occupied_voxels()[k].probability == terrain_.occupied_voxels()[k].probability;
  }
  for (std::size_t k = 0; raises_only && k < terrain_.obstacles().size(); ++k) {
    raises_only = SameObstacle(terrain.obstacles()[k], terrain_.obstacles()[k]);
  }
  int col0 = terrain.cols(), row0 = terrain.rows(), col1 = -1, row1 = -1;
  for (int r = 0; raises_only && r < terrain.rows(); ++r) {
    for (int c = 0; c < terrain.cols(); ++c) {
      const bool was = terrain_.walkable(c, r), is = terrain.walkable(c, r);
      const bool same = terrain.has_ground(c, r) == terrain_.has_ground(c, r) &&
                        (!terrain.has_ground(c, r) || (terrain.height(c, r) == terrain_.height(c, r) &&
                                                       terrain.normal(c, r) == terrain_.normal(c, r) &&
                                                       terrain.friction(c, r) == terrain_.friction(c, r)));
      if (same) continue;
      if (is && !(was && terrain.height(c, r) == terrain_.height(c, r) && terrain.normal(c, r) == terrain_.normal(c, r) &&
                  terrain.friction(c, r) <= terrain_.friction(c, r))) {
        raises_only = false;
        break;
      }
      col0 = std::min(col0, c);
      row0 = std::min(row0, r);
      col1 = std::max(col1, c);
      row1 = std::max(row1, r);
    }
  }
  terrain_ = terrain;  // the graph refers to this member, which keeps its address
  if (graph_ == nullptr) return false;
  if (!raises_only) {
    graph_.reset();
    return false;
  }
  if (col1 >= 0) graph_->RefreshFootholds(col0, row0, col1, row1);
  return true;
}

FootstepPlan FootstepReplanner::Plan(const Stance& start) {
  const auto t0 = internal::Clock::now();
  const internal::Clock::time_point deadline = internal::CheckPlanInputs(start, goal_, options_, t0);
  auto out_of_time = [&](const TimeLimitReached& error) {
    FootstepPlan plan;
    plan.cost_model = cost_model_->description();
    plan.start = start;
    plan.reason = internal::TimeLimitDuringPrecomputation(options_, error);
    plan.statistics.plan_seconds = std::chrono::duration<double>(internal::Clock::now() - t0).count();
    return plan;
  };
  try {
    if (graph_ == nullptr) {
      graph_ = std::make_unique<StanceGraph>(terrain_, *cost_model_, geometry_, options_, goal_, deadline);
    } else if (graph_->ignores_friction()) {
      // An earlier Plan() diagnosed a failure with friction ignored: restore the heuristic.
      graph_->set_ignore_friction(false, deadline);
    }
  } catch (const TimeLimitReached& error) {
    graph_.reset();  // incomplete: the next Plan() starts over
    return out_of_time(error);
  }
  return internal::PlanOnStanceGraph(*graph_, terrain_, start, goal_, *cost_model_, options_, t0, deadline);
}

}  // namespace cairn::planning
