#pragma once

#include <cairn/planning/footstep/footstep_plan.h>
#include <cairn/planning/locomotion/walking_model.h>
#include <cairn/planning/locomotion/walking_objective.h>

namespace cairn::planning {

/// After the search, refines each step's parameters p continuously (thesis 2.4.1a): SLSQP on the exact step
/// model at the step's true displacement and friction limit, warm-started from the table's (interpolated) values.
/// A step whose refinement fails keeps its table values. Updates the plan's totals; returns the number of steps
/// refined. Plans that were not found are left alone.
int RefineFootstepPlan(const WalkingModel& model, WalkingObjective objective, FootstepPlan* plan);

}  // namespace cairn::planning
