#pragma once

#include <string>
#include <vector>

#include "cairn/common/atomic_output_directory.h"
#include "cairn/multibody/model.h"
#include "cairn/planning/footstep/footstep_plan.h"
#include "cairn/planning/scenarios/footstep_scenario.h"
#include "cairn/planning/trajectory/collision_penalty.h"
#include "cairn/planning/trajectory/whole_body_trajectory.h"

namespace cairn::cli {

/// trajectory.json of `cairn plan --whole-body`: the report, the coordinate names and per waypoint its time,
/// stance, label, contacts, COM, clearance and q.
std::string WholeBodyTrajectoryJson(const planning::WholeBodyTrajectory& trajectory);

/// A PNG of the robot at every waypoint (its links as segments from each body to its parent, COM dots), side view
/// (x-z) above top view (x-y), with the environment boxes in grey and the ground line (thesis Figs. 2.14-2.15).
/// Throws std::runtime_error if the picture cannot be encoded, std::invalid_argument if its extent is not finite
/// or larger than 50 m.
std::string WholeBodyTrajectoryPng(const multibody::Model& model, const planning::WholeBodyTrajectory& trajectory,
                                   const std::vector<planning::EnvironmentBox>& environment);

/// The --whole-body step of `cairn plan`: optimises the plan's whole-body trajectory (OptimizeWholeBodyTrajectory,
/// default options) for the project's humanoid (data/robots/cairn_humanoid.urdf, floating base) among the
/// scenario's obstacles, prints a summary line (or the report's reason when it fails), and, with `out`, writes
/// trajectory.json and trajectory.png into it (uncommitted). Returns 0, or 1 when the optimisation failed (the
/// files are still written: failures are results).
/// `terrain` (may be null) is the ground the plan was made on; the soles are laid on it (tilted on slopes).
int RunWholeBody(const planning::FootstepScenario& scenario, const planning::FootstepPlan& plan,
                 const planning::TerrainMap* terrain, bool quiet, AtomicOutputDirectory* out);

}  // namespace cairn::cli
