#pragma once

#include <cairn/planning/locomotion/step_cost_model.h>
#include <cairn/planning/locomotion/walking_model.h>
#include <cairn/planning/locomotion/walking_objective.h>
#include <cairn/planning/locomotion/walking_pattern_generator.h>

namespace cairn::planning {

/// Settings of OptimizeTransition.
struct TransitionOptimizerOptions {
  /// Evaluation budget of the global DIRECT stage (NLopt GN_ORIG_DIRECT).
  int direct_max_evaluations{150};
  /// Evaluation budget of the SLSQP stage.
  int slsqp_max_evaluations{200};
  /// Sampling of each evaluated step.
  WalkingPatternOptions pattern;
};

/// The minimum-cost step (thesis eq. 2.4):
///     c = min_p objective(d, p)  s.t.  RCOF(d, p) <= mu_allowed,  Psi(d, p) feasible,  lower <= p <= upper,
/// over p = (t_ds, t_sw, com_height), solved through cairn::optimization with NLopt.
///
/// Without `warm_start`: GN_ORIG_DIRECT over the parameter box, then LD_SLSQP from its best point (the oracle's
/// precompute). With `warm_start` (e.g. a table entry): SLSQP alone from it (the planner's refinement). The
/// better feasible point of the stages is returned; the result is deterministic.
///
/// Constraints are smooth rows rather than the non-smooth max of eq. 2.2: per contact sample
/// (F_T - mu F_N) / (m g) <= 0 (equivalent to F_T / F_N <= mu with F_N > 0), and per contact leg and sample
/// the leg-length and posture (joint-limit) rows of Psi; gradients are central finite differences. Variables,
/// cost and rows are scaled to order one for SLSQP (see the source). The returned point is
/// re-evaluated and accepted only if StepEvaluator reports it feasible with RCOF <= mu_allowed (1e-9 slack).
///
/// A displacement outside the reach box, one without a periodic gait (StepInfeasibility::kSolesOverlap), or
/// mu_allowed == 0 returns feasible == false without solving.
/// Throws std::invalid_argument for a negative or non-finite mu_allowed, a non-finite displacement or a
/// warm start outside the parameter bounds.
TransitionCost OptimizeTransition(const WalkingModel& model, const StepDisplacement& d, double mu_allowed,
                                  WalkingObjective objective, const StepParameters* warm_start = nullptr,
                                  const TransitionOptimizerOptions& options = TransitionOptimizerOptions());

}  // namespace cairn::planning
