#pragma once

#include <string>

namespace cairn::planning {

/// Most stances (the start plus one per step) a whole-body problem accepts: 200. Each stance adds two waypoints
/// of nq variables and a dense block of collision and torque Jacobians, so the bound keeps a wrong plan from
/// building a problem of unbounded size.
inline constexpr int kMaxTrajectoryStances = 200;

/// Parameters of the whole-body trajectory problem (thesis 2.5.1b, problem 2.9) and of its solve.
struct TrajectoryOptimizerOptions {
  /// Collision penalty weight alpha of eq. 2.9a (thesis: 50).
  double collision_weight{50.0};
  /// Distance at which the penalty starts against the environment, m (thesis: 2.5 cm).
  double d_safe{0.025};
  /// Margin of the penalty between two robot links, m (0: no self-collision term).
  double self_margin{0.01};
  /// Collision samples between consecutive waypoints (0: waypoints only), at fractions k / (n + 1).
  int samples_between{1};
  /// Weight of the squared static torques, each divided by its joint's effort limit (eq. 2.10; about 0.1-1 per
  /// waypoint). The thesis' alpha = 50 weighs a hinge in metres against torques in trajopt's units, so with
  /// these units a link pressed by a strong torque gradient can settle a little inside d_safe: raise
  /// collision_weight where the clearance must be exact.
  double torque_weight{1.0};
  /// Weight of the smoothness term sum_t |q_{t+1} - q_t|^2 over the joint coordinates (not in eq. 2.9): it makes
  /// the joints that barely change the torques (wrists, neck) well determined, so the solver converges, and keeps
  /// them from swinging between waypoints. Small against the torque term (1 % of its weight).
  double smoothness_weight{1e-2};
  /// Weight of the waist-orientation smoothness term sum_t |2 (quat_{t+1} - quat_t)|^2 over the floating base's
  /// quaternion (BaseRotationChange; about theta^2 for a rotation of theta rad between consecutive waypoints, roll,
  /// pitch and yaw together; not in eq. 2.9). Without it the waist's pitch and yaw are free wherever the torques
  /// barely see them and swing by 20-25 degrees between waypoints. 0: off.
  double base_rotation_smoothness_weight{0.0};
  /// Weight of the posture term sum_t |q_t - q_neutral|^2 over the joints (not in eq. 2.9; q_neutral is the
  /// model's zero posture): it pins the directions the torques do not see at all (an arm turning about its own
  /// axis), so a solution is isolated and every solver finds the same one.
  double posture_weight{1e-3};
  /// Margin of the COM inside the support polygon, m (eq. 2.9c).
  double com_margin{0.02};
  /// Sole rectangle (length along the foot, width), m, centred on the sole frame.
  double sole_length{0.24};
  double sole_width{0.14};
  /// Contact frames of the feet.
  std::string left_sole_frame{"l_sole"};
  std::string right_sole_frame{"r_sole"};
  /// The frame whose roll is held at zero (2.9d); the thesis' waist is the floating base.
  std::string waist_frame{"pelvis"};
  /// Height of the flat ground under the plan, m: every link not in contact keeps d_safe from this plane
  /// (CollisionPenalty's closed-form ground term). The solve lowers it by the deepest reach of a tilted sole
  /// target's corner below that sole's centre, so that it does not cut into a sole laid on a slope. NaN: no
  /// ground.
  double ground_height{0.0};
  /// With a terrain given to the solve: the ground term measures each point's clearance from the plane of the
  /// terrain cell under it instead (CollisionPenalty's ground_terrain), so a swing foot keeps d_safe from a slope
  /// or a stair tread. Off by default: on perceived terrain the cells' noisy heights make the term jump from cell
  /// to cell and the solve stalls at its iteration limit (the cloth mock-up of the main diagram, measured
  /// 2026-12-07); on the scenarios' exact slopes it solves (docs/walk.md, "Slopes").
  bool ground_follows_terrain{false};
  /// Solver by name (MakeSolver): "ipopt" (default) or e.g. "nlopt:SLSQP" for small problems.
  std::string solver{"ipopt"};
  /// Ipopt's Hessian of the Lagrangian:
  /// - "gauss-newton": J'J for the squared torques (the least-squares cost's Gauss-Newton matrix, Ipopt option
  ///   least_squares_hessian) and 2 sum J_p' J_p for the collision hinges (CollisionHessian::kGaussNewton);
  ///   analytic for the quadratic terms and differences of the analytic Jacobians for the constraints, whose
  ///   curvature the multipliers need;
  /// - "exact": every term's Hessian, the kinematic ones by differences of their analytic Jacobians (2 nq
  ///   Jacobian evaluations per term and iteration);
  /// - "limited-memory": L-BFGS.
  std::string hessian{"exact"};
  /// Solver iteration budget (Ipopt max_iter; NLopt maxeval is 50 times it).
  int max_iterations{500};
  /// Convergence and constraint tolerance given to the solver.
  double tolerance{1e-6};
  /// Stances per window when solving in a receding window (0: the whole plan in one problem).
  int window_stances{0};
  /// Pelvis height of the warm-start posture above the stance's mean foot height, m.
  double nominal_pelvis_height{0.80};
};

/// Throws std::invalid_argument naming the first option out of range and its valid range.
void ValidateTrajectoryOptimizerOptions(const TrajectoryOptimizerOptions& options);

}  // namespace cairn::planning
