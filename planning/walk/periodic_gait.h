#pragma once

#include <string>
#include <vector>

#include <cairn/multibody/plant/terrain_box.h>
#include <cairn/planning/footstep/footstep_plan.h>
#include <cairn/planning/locomotion/step_cost_model.h>
#include <cairn/planning/locomotion/walking_model.h>
#include <cairn/planning/locomotion/walking_objective.h>

namespace cairn::planning {

/// A symmetric periodic gait (thesis 2.3.3: "a sequence of 6 symmetric steps of constant step length, width,
/// height and p"): `num_steps` steps of one displacement and one set of parameters, the feet alternating, from a
/// start stance that already has that displacement (the left foot placed by it beside the right one), so every
/// step, the first included, is the same step mirrored; then one closing step brings the trailing foot beside the
/// leading one (displacement (0, dy, 0, 0), same parameters), so the walk ends at rest on both feet (the thesis'
/// patterns "start and finish with zero COM velocity"; measured: stopping on a staggered stance after a brisk
/// gait tips the robot over its last support foot). With dtheta != 0 the feet alternate between the two headings
/// (toe-out); with dz != 0 the gait climbs or descends a staircase of one tread per foothold.
struct PeriodicGait {
  StepDisplacement displacement;
  StepParameters parameters;
  int num_steps{6};
};

/// Most steps a PeriodicGait may have.
inline constexpr int kMaxPeriodicGaitSteps = 100;

/// The gait as a footstep plan of num_steps + 1 steps (the last is the closing step): the right foot at the origin
/// with heading 0 and the left foot beside it, then the right foot first; each step carries `mu_allowed` and the
/// analytic model's prediction for its displacement and the parameters (StepEvaluator; `transition.feasible` is its
/// Psi, and cost is the objective's value even when Psi fails, so a plan can be walked to see what the plant makes
/// of a step the model rejects). Throws
/// std::invalid_argument naming the value for num_steps outside [1, kMaxPeriodicGaitSteps], a non-finite
/// displacement or parameter, a displacement outside the model's reach, parameters outside its bounds, or
/// mu_allowed not in (0, 10].
FootstepPlan PeriodicGaitPlan(const PeriodicGait& gait, const WalkingModel& model, WalkingObjective objective,
                              double mu_allowed);

/// The ground a plan stands on in the plant, with Coulomb friction `friction`: for a plan whose footholds all lie
/// at one height, one level floor 1 m thick reaching 1 m beyond every foothold; otherwise one tread per foothold,
/// 1 m thick, its top at the foothold's height, the sole's rectangle (`foot_length` by `foot_width`, turned with
/// the foot) grown by `margin` on every side. Throws std::invalid_argument for sizes not > 0, a margin outside
/// [0, 0.1] m, friction outside [0, 10], a plan without steps, or two treads at different heights that overlap
/// (naming the footholds: no staircase holds both; a periodic gait with dz != 0 needs 2|dx| >= foot_length).
std::vector<multibody::TerrainBox> PeriodicGaitTerrain(const FootstepPlan& plan, double foot_length,
                                                       double foot_width, double friction, double margin = 0.01);

}  // namespace cairn::planning
