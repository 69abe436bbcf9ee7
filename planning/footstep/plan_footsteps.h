#pragma once

#include <cairn/planning/footstep/biped_geometry.h>
#include <cairn/planning/footstep/foot_pose.h>
#include <cairn/planning/footstep/footstep_plan.h>
#include <cairn/planning/footstep/footstep_planner_options.h>
#include <cairn/planning/footstep/terrain_map.h>
#include <cairn/planning/locomotion/step_cost_model.h>

namespace cairn::planning {

/// Plans footsteps and their timing from `start` to `goal` over friction-annotated `terrain` (thesis 2.4.1):
/// ARA* over the StanceGraph, each step priced by `cost_model` under the smallest friction of its three feet,
/// returning the best plan found within `options.search.time_limit` together with its suboptimality bound. The
/// time limit covers the whole call: the heuristic's precomputation over the lattice, the search, and the second
/// search that explains a failure.
///
/// Either foot may move first. The start feet are snapped to the lattice. No plan is a result with a reason:
/// the start or goal has no support, the goal is unreachable, every way there needs more friction than the
/// terrain offers (told apart by a second search that ignores friction), or the time ran out first (also during
/// the precomputation).
///
/// Throws std::invalid_argument only for invalid options or geometry (including a start or goal stance that
/// cannot stand: StanceGeometryProblem()).
FootstepPlan PlanFootsteps(const TerrainMap& terrain, const Stance& start, const StanceGoal& goal,
                           const StepCostModel& cost_model, const BipedGeometry& geometry,
                           const FootstepPlannerOptions& options);

}  // namespace cairn::planning
