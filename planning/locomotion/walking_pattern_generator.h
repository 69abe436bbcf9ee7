#pragma once

#include <vector>

#include <Eigen/Core>

#include <cairn/planning/locomotion/step_cost_model.h>

namespace cairn::planning {

/// Which feet carry the robot during a sample of a step.
enum class ContactPhase {
  kDoubleSupport,  ///< both the previous foot f_{j-1} and the stance foot f_j (weight moving onto f_j)
  kSingleSupport,  ///< the stance foot f_j alone while f_{j-1} swings to f_{j+1}
};

/// A foothold in the stance frame: sole centre and yaw.
struct Foothold {
  Eigen::Vector3d position{Eigen::Vector3d::Zero()};
  double yaw{0.0};
};

/// How the pattern generator samples a step.
struct WalkingPatternOptions {
  /// Samples per phase (double support and swing), endpoints included; at least 2.
  int samples_per_phase{16};
};

/// One step of a symmetric periodic gait, sampled: the COM, its derivatives and the ZMP reference over
/// t in [0, t_ds + t_sw], expressed in the stance foot's sole frame f_j (x forward, y toward the new foot).
///
/// Columns are samples: the first `samples_per_phase` lie in double support (t = 0 .. t_ds), the rest in the
/// swing phase (t = t_ds .. t_ds + t_sw); the phase boundary appears in both halves.
struct WalkingPattern {
  StepDisplacement displacement;
  StepParameters parameters;
  Foothold previous_foot;  ///< f_{j-1}: where the swing foot lifts off
  Foothold stance_foot;    ///< f_j: the origin
  Foothold next_foot;      ///< f_{j+1}: where it lands
  Eigen::VectorXd time;
  std::vector<ContactPhase> phase;
  Eigen::Matrix3Xd com;
  Eigen::Matrix3Xd com_velocity;
  Eigen::Matrix3Xd com_acceleration;
  Eigen::Matrix3Xd zmp;  ///< the ZMP reference (on the line between the sole centres)
  /// Share of the vertical load on the stance foot f_j: the ZMP's interpolation fraction in double support
  /// (the ZMP divides the segment between the sole centres as the two foot forces do), 1 in swing.
  Eigen::VectorXd stance_load_fraction;
  /// Slope k = dz / dx of the plane through the footholds (0 on level ground).
  double slope{0.0};
};

/// Generates the COM motion of one step (f_{j-1}, f_j) -> (f_j, f_{j+1}) of a periodic gait with constant
/// displacement `d` and parameters `p`, as the thesis simulated its steps (2.3.3).
///
/// Footholds: f_{j+1} at (dx, dy, dz) with yaw dtheta and, by the gait's mirror symmetry, f_{j-1} at
/// (-dx, dy, -dz) with yaw 0. The yaw enters only the landing foot's orientation: a periodic gait with a
/// constant mirrored yaw would be a zig-zag of splayed feet (turning alternates opening and closing steps), and
/// the thesis' energy and RCOF models had no yaw input at all. Yaw moments at the contacts are not modelled.
///
/// ZMP reference: from f_{j-1}'s sole centre to f_j's during double support along the straight segment with
/// the cubic 3s^2 - 2s^3 (zero velocity at both ends), then fixed at f_j's centre during the swing.
///
/// COM height: the three footholds lie on the plane z = k x with k = dz / dx (the ramp of the periodic
/// staircase or slope), and the COM moves on the parallel plane z = h + k x, h = p.com_height: it follows the
/// feet, rising by dz per step, and its height above the ZMP is exactly h whenever it is above the ZMP (on
/// level ground, always). The ZMP reference lies on the ramp (z_zmp = k x_zmp). For this constraint plane the
/// cart-table equation xy'' (z - z_zmp) = (z'' + g)(xy - zmp_xy) reduces exactly to the linear inverted
/// pendulum xy'' = (g / h)(xy - zmp_xy) (Kajita et al., IROS 2001, "The 3D linear inverted pendulum mode"),
/// so omega^2 = g / h is constant on slopes and steps too, and every phase has a closed form: cosh/sinh plus
/// the particular solution p + p''/omega^2 of the cubic ZMP (exact, as p'''' = 0). z is not constant: it
/// varies with x, so the vertical force m (z'' + g) and with it RCOF and E_COM see the climb.
///
/// Boundary-value solution (no preview control): the step must map onto the next one, i.e. the state at t = T
/// translated to f_{j+1} and mirrored in y equals the state at t = 0. The flow over the step is an affine map
/// s(T) = Phi s(0) + s_p of s = (x, y, vx, vy), so periodicity is a 4x4 linear system for s(0), solved exactly.
///
/// Throws std::invalid_argument for non-finite input, a non-positive duration or height, dz != 0 with dx == 0
/// (consecutive footholds of the same foot would stack vertically: no periodic gait exists), or bad options.
WalkingPattern GenerateWalkingPattern(const StepDisplacement& d, const StepParameters& p, double gravity,
                                      const WalkingPatternOptions& options = WalkingPatternOptions());

/// Same, writing into `pattern` and reusing its buffers (no allocation when the sample count is unchanged).
void GenerateWalkingPattern(const StepDisplacement& d, const StepParameters& p, double gravity,
                            const WalkingPatternOptions& options, WalkingPattern& pattern);

}  // namespace cairn::planning
