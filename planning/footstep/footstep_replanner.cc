#include <cairn/planning/footstep/footstep_replanner.h>

#include <chrono>
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
