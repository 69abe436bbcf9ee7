#pragma once

#include <memory>
#include <vector>

#include <cairn/multibody/model.h>
#include <cairn/planning/footstep/footstep_plan.h>
#include <cairn/planning/footstep/terrain_map.h>
#include <cairn/planning/trajectory/collision_penalty.h>
#include <cairn/planning/trajectory/trajectory_optimizer_options.h>
#include <cairn/planning/trajectory/whole_body_trajectory.h>

namespace cairn::planning {

/// Solves problem (2.9) for a footstep plan (thesis 2.5.1b): builds the waypoints (MakeWaypointSpecs), warm
/// starts every waypoint by inverse kinematics, and solves with options.solver, either the whole plan as one
/// NLP (window_stances = 0, or at least the number of stances) or in a receding window of window_stances
/// stances: each window's first two waypoints (a stance's start and mid-swing) are kept and the next window
/// starts from the last kept waypoint, held fixed (thesis 5.3.2: plan a stance or two ahead while walking).
///
/// Failures are results: a plan that was not found, or a solve that does not converge or ends infeasible,
/// returns found = false with the report naming the most violated rows ("stance 3 start, l_sole position off
/// by 0.21 m"); the waypoints then hold the best point the solver returned (or are empty if no solve ran).
/// Throws std::invalid_argument only for a null model, options out of range, a model without the option's
/// frames, or a plan with more than kMaxTrajectoryStances stances or a step without a positive swing time.
///
/// `terrain` (may be null): the ground the plan stands on. Its normals tilt the sole targets (MakeWaypointSpecs)
/// and the collision terms keep links clear of it (CollisionPenalty's ground_terrain; options.ground_height where
/// it has no cell); without it every sole is held level over the plane at options.ground_height.
WholeBodyTrajectory OptimizeWholeBodyTrajectory(std::shared_ptr<const multibody::Model> model, const FootstepPlan& plan,
                                                const std::vector<EnvironmentBox>& environment,
                                                const TrajectoryOptimizerOptions& options = TrajectoryOptimizerOptions(),
                                                const TerrainMap* terrain = nullptr);

}  // namespace cairn::planning
