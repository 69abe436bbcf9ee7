#pragma once

#include <memory>
#include <string>
#include <vector>

#include <Eigen/Core>

#include <cairn/multibody/model.h>
#include <cairn/planning/stabilization/stabilizer_options.h>
#include <cairn/planning/trajectory/whole_body_trajectory.h>

namespace cairn::planning {

/// Contact bits of a knot or sample: which soles are on the ground.
inline constexpr int kLeftSoleContact = 1;
inline constexpr int kRightSoleContact = 2;

/// A posture the interpolation passes through with zero velocity (Hermite) or continuously (spline).
struct InterpolationKnot {
  double time{0.0};               ///< s
  Eigen::VectorXd q;              ///< configuration (unit quaternion)
  /// The reference ZMP at this knot: the horizontal COM of q, except at a touch-down (see MakeInterpolationKnots).
  Eigen::Vector2d com{Eigen::Vector2d::Zero()};
  int contacts{0};                ///< soles on the ground in q (kLeftSoleContact | kRightSoleContact)
  std::string label;              ///< e.g. "stance 2 lift-off"
};

/// The knots of a whole-body trajectory (thesis 2.5.1c). With options.contact_timing false they are the
/// optimiser's waypoints at their own times, the reference ZMP their COM projections (the thesis, the default).
/// With it true the waypoints are re-timed to the plan's contact events, because the optimiser's stance-start
/// posture at t_j already has the COM over the next stance foot and its mid-swing posture follows at
/// t_j + t_ds + t_sw / 2, so interpolating them directly lifts the swing foot during the double support. Per step
/// j (t_ds and t_sw recovered from the waypoint times: t_sw = 2 (t_j+1 - t_mid), t_ds = (t_mid - t_j) - t_sw / 2):
///   t_j            stance j start waypoint, touch-down (the first knot: "start")
///   t_j + t_ds     the same posture, lift-off (held through the double support)
///   t_mid          mid-swing waypoint
/// and after the last step the final stance's waypoint at t_M and t_M + t_ds of the last step. The reference ZMP is
/// the knots' COM projection (inside the support polygon at every knot, as problem 2.9 has it) except at a
/// touch-down, where it is still the mid-swing COM: it stays over the stance foot through the single support and
/// crosses to the next stance foot during the double support, where both feet carry it. The posture's own COM
/// moves across during the swing; the stabiliser's COM offsets make the motion's ZMP follow the reference.
///
/// Throws std::invalid_argument if the trajectory was not found, is empty, has configurations of the wrong size,
/// non-increasing times, or (with contact_timing) waypoints that do not alternate stance start / mid-swing or a
/// step whose recovered t_ds is negative; or if the model lacks the option's frames.
std::vector<InterpolationKnot> MakeInterpolationKnots(std::shared_ptr<const multibody::Model> model,
                                                      const WholeBodyTrajectory& trajectory,
                                                      const StabilizerOptions& options);

}  // namespace cairn::planning
