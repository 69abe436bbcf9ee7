#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <cairn/planning/footstep/foot_pose.h>
#include <cairn/planning/locomotion/step_cost_model.h>

namespace cairn::planning {

/// One transition s_{j-1} -> s_j of a plan: the swing foot leaves its old foothold and lands on `pose`.
struct PlannedStep {
  FootSide side{FootSide::kLeft};  ///< the foot that moves
  FootPose pose;                   ///< where it lands
  /// The landing pose relative to the stance foot, mirrored as StepDisplacement documents.
  StepDisplacement displacement;
  /// Friction the step may use: the smallest chance-constrained friction Q_{1-eta} under the three feet
  /// involved (thesis eq. 2.3 / 5.3).
  double mu_allowed{0.0};
  /// The step's optimal parameters and predictions (cost, E_COM, heat, RCOF, duration).
  TransitionCost transition;
};

/// Search statistics of a plan.
struct FootstepPlanStatistics {
  std::int64_t expansions{0};
  std::int64_t generated{0};  ///< distinct stances seen
  double plan_seconds{0.0};   ///< wall time of the whole call
  double first_plan_seconds{-1.0};  ///< wall time to the first plan (-1: none)
  /// Proven suboptimality bound of the returned plan (1: optimal for the cost model).
  double epsilon{0.0};
  int improvements{0};             ///< plans published by the anytime search
  std::int64_t rejected_support{0};   ///< candidate footholds without support, too steep, or off the map
  std::int64_t rejected_collision{0};  ///< candidate stances whose body box hits an obstacle or whose soles overlap
  std::int64_t rejected_friction{0};  ///< candidate steps feasible on high friction but not under mu_allowed
};

/// The result of footstep planning: a sequence of steps from the start stance to the goal, or the reason there
/// is none. Not finding a plan is a result, not an error.
struct FootstepPlan {
  bool found{false};
  /// Why no plan was found (empty when found).
  std::string reason;
  /// The start stance as planned (snapped to the planner's lattice and put on the terrain).
  Stance start;
  /// Which foot moves first.
  FootSide first_side{FootSide::kLeft};
  std::vector<PlannedStep> steps;
  /// Sum of the steps' objective values.
  double cost{0.0};
  /// Sum of the steps' E_COM + heat, J: the energy estimate whatever the objective.
  double energy{0.0};
  double duration{0.0};  ///< s
  double distance{0.0};  ///< horizontal path length of the stance midpoint, m
  double max_rcof{0.0};
  /// Smallest mu_allowed - rcof over the steps: how far the plan stays from slipping.
  double min_friction_margin{0.0};
  /// Description of the cost model that priced the steps.
  std::string cost_model;
  FootstepPlanStatistics statistics;

  /// Recomputes cost, energy, duration, distance, max_rcof and min_friction_margin from `start` and `steps`.
  void UpdateTotals();
  /// The stance after step `k` (k = -1: the start stance).
  Stance StanceAfter(int k) const;
};

}  // namespace cairn::planning
