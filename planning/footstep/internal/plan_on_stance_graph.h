#pragma once

#include <chrono>
#include <string>

#include <cairn/planning/footstep/foot_pose.h>
#include <cairn/planning/footstep/footstep_plan.h>
#include <cairn/planning/footstep/footstep_planner_options.h>
#include <cairn/planning/footstep/stance_graph.h>
#include <cairn/planning/footstep/terrain_map.h>
#include <cairn/planning/footstep/time_limit_reached.h>
#include <cairn/planning/locomotion/step_cost_model.h>

// The parts of PlanFootsteps() that FootstepReplanner shares with it.
namespace cairn::planning::internal {

using Clock = std::chrono::steady_clock;

/// Throws std::invalid_argument for a start or goal stance that cannot stand or a non-positive time limit;
/// returns the deadline of a call that started at `t0`.
Clock::time_point CheckPlanInputs(const Stance& start, const StanceGoal& goal, const FootstepPlannerOptions& options,
                                  Clock::time_point t0);

/// The reason of a plan whose heuristic precomputation ran out of time.
std::string TimeLimitDuringPrecomputation(const FootstepPlannerOptions& options, const TimeLimitReached& error);

/// PlanFootsteps() after the graph's construction: checks the feet, searches from `start`, explains a failure
/// (which leaves the graph ignoring friction). `graph` must have been built for `terrain`, `goal`, `cost_model`
/// and `options`; it may have served earlier searches.
FootstepPlan PlanOnStanceGraph(StanceGraph& graph, const TerrainMap& terrain, const Stance& start,
                               const StanceGoal& goal, const StepCostModel& cost_model,
                               const FootstepPlannerOptions& options, Clock::time_point t0,
                               Clock::time_point deadline);

}  // namespace cairn::planning::internal
