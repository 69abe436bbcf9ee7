#pragma once

#include <Eigen/Core>

#include <cairn/planning/locomotion/step_cost_model.h>
#include <cairn/planning/locomotion/walking_model.h>
#include <cairn/planning/locomotion/walking_pattern_generator.h>

namespace cairn::planning {

/// Why a step fails the feasibility test Psi (the first reason found, in this order).
enum class StepInfeasibility {
  kNone,
  kOutOfReach,             ///< displacement outside WalkingModel::reach()
  kSolesOverlap,           ///< dz != 0 but 2|dx| < foot length: the same foot's footholds overlap in plan at
                           ///< different heights, so no periodic gait exists (the pattern is not generated)
  kParametersOutOfBounds,  ///< p outside [parameter_lower, parameter_upper]
  kFootLifts,              ///< a contact's normal force is not positive (the COM would have to fall faster than g)
  kLegTooLong,             ///< hip-to-ankle distance above leg().leg_length_max (knee straighter than allowed)
  kLegTooShort,            ///< hip-to-ankle distance below leg().leg_length_min (knee more bent than allowed)
  kLegPosture,             ///< a contact leg's posture exceeds its joint limits or the leg-torque table's box
  kZmpOutsideSupport,      ///< the ZMP leaves the support polygon
};

/// "none", "out of reach", ...
const char* to_string(StepInfeasibility reason);

/// Everything one step's pattern predicts (thesis 2.3: energy, slippage and feasibility).
///
/// Contact samples: the stance foot f_j at every pattern sample, followed by the previous foot f_{j-1} at the
/// double-support samples; the per-contact-sample vectors below use this layout (its size depends only on the
/// options, so optimisers can turn them into a fixed set of constraint rows).
struct StepEvaluation {
  bool feasible{false};
  StepInfeasibility infeasibility{StepInfeasibility::kNone};
  /// E_COM = integral |v . F| dt (eq. 2.1), J. Since v . F = dE/dt for the COM's mechanical energy
  /// E = m|v|^2/2 + m g z, it is computed as the total variation of E over the samples: exact whenever E is
  /// monotone between samples, never above the true value, and never below |E(T) - E(0)| = m g |dz|.
  double com_work{0.0};
  /// Motor heat of both legs, sum_i R_i I_i^2 dt with I = tau / (r K_tau) (eq. 2.6, second term), J.
  double heat{0.0};
  /// integral sum_i tau_i^2 dt over both legs' joints, N^2 m^2 s.
  double squared_torque{0.0};
  /// max over contact samples of |F_T / F_N| in the contact surface's frame (eq. 2.2); +inf if a foot lifts.
  double rcof{0.0};
  /// t_ds + t_sw, s.
  double duration{0.0};
  /// Extremes of the contact legs' hip-to-ankle distance over the step, m.
  double leg_length_min{0.0};
  double leg_length_max{0.0};
  /// Largest distance of the ZMP outside the support polygon over the samples, m (0 when always inside).
  double zmp_outside_support{0.0};
  /// Per contact sample: ground force normal to the contact surface and its tangential magnitude, both for
  /// the TOTAL force m (a + g e_z) (each foot carries a share of it with the same direction, so the ratio is
  /// the foot's ratio), N.
  Eigen::VectorXd normal_force;
  Eigen::VectorXd tangential_force;
  /// Per contact sample: hip-to-ankle distance, m.
  Eigen::VectorXd leg_length;
  /// Per contact sample: how far the leg's posture exceeds its joint limits (LegTorqueTable::JointLimitExcess)
  /// or the table's box of lean angles, rad (<= 0 when feasible).
  Eigen::VectorXd leg_posture_excess;
};

/// Evaluates steps of a periodic gait on a WalkingModel: the pattern (GenerateWalkingPattern), then COM work,
/// RCOF, heat, squared torque and the feasibility Psi. Holds preallocated buffers, so one evaluator per thread;
/// Evaluate does not allocate once the buffers are sized.
///
/// Modelling choices (the thesis measured these in physics simulation; here they follow from the model):
/// - Contact surfaces (RCOF): both feet stand on the plane through the footholds, a uniform slope dz / dx along
///   x (the plane the COM follows, see GenerateWalkingPattern). For stairs, whose treads are level, this
///   overestimates RCOF: conservative.
/// - Load sharing in double support: the two foot forces have the direction of the total force and divide it
///   as the ZMP divides the segment between the sole centres (share w on f_j, 1 - w on f_{j-1}); the forces then
///   add up to the total force acting at the ZMP.
/// - Static torques (heat, squared torque): at each sample every contact leg carries its share of the robot's
///   weight, w m g, vertically, at its sole centre shifted by the COM's horizontal offset from the ZMP, so that
///   the contact forces balance gravity on the floating base at the sampled posture (single support: the whole
///   weight under the COM); the torques come from the LegTorqueTable. The swing leg holds only its own weight
///   along a path from lift-off to touch-down raised by swing_height. Leg postures take the pelvis at the COM's
///   standing offset, upright, with yaw dtheta/2; foot yaw relative to the pelvis is neglected in the torques.
/// - Psi: reach box, parameter bounds, positive normal force, leg length within the knee range and every leg
///   joint within its URDF limits (all contact legs, every sample; the limits through the torque table's
///   interpolated margins), and the ZMP inside the support polygon (stance sole in
///   swing, the convex hull of both soles in double support). The generated COM realises the ZMP reference
///   exactly (the tests recompute it from finite differences) and the reference runs along the segment
///   between the sole centres, which the hull always contains: with this reference the check cannot fail; it
///   is evaluated so that Psi stays complete if the reference changes.
class StepEvaluator {
 public:
  /// The evaluator keeps a reference to `model`, which must outlive it.
  explicit StepEvaluator(const WalkingModel& model, const WalkingPatternOptions& options = WalkingPatternOptions());

  /// Evaluates the step with displacement `d` and parameters `p`. All quantities are computed even when the
  /// step is infeasible, except for kSolesOverlap (no pattern exists: forces, legs and energies are left 0 and
  /// rcof infinite). The reference stays valid until
  /// the next call. Throws std::invalid_argument for non-finite input or non-positive durations/height.
  const StepEvaluation& Evaluate(const StepDisplacement& d, const StepParameters& p);

  /// The pattern of the last Evaluate.
  const WalkingPattern& pattern() const { return pattern_; }
  /// The model.
  const WalkingModel& model() const { return model_; }
  /// The sampling options.
  const WalkingPatternOptions& options() const { return options_; }
  /// Number of contact samples (size of the per-contact-sample vectors).
  int num_contact_samples() const { return 3 * options_.samples_per_phase; }

 private:
  const WalkingModel& model_;
  WalkingPatternOptions options_;
  WalkingPattern pattern_;
  StepEvaluation evaluation_;
};

}  // namespace cairn::planning
