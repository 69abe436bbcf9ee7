#pragma once

#include <memory>
#include <string>
#include <vector>

#include <Eigen/Core>

#include <cairn/multibody/model.h>
#include <cairn/planning/stabilization/interpolation_knots.h>

namespace cairn::planning {

/// Dense interpolation of knots (thesis 2.5.1c). "hermite": per segment [t_k, t_k+1] with s = (t - t_k) / T,
/// h(s) = 3 s^2 - 2 s^3, every joint coordinate and the base position move as y_k + h(s) (y_k+1 - y_k) (zero
/// velocity at the knots, for smooth contact transitions) and the base orientation as slerp(quat_k, quat_k+1, h(s))
/// (on the unit sphere, the shorter arc). "spline": a natural cubic spline (C2) through the knots for the joints,
/// the base position and the base orientation's rotation vector r_k = log(R_0^T R_k) relative to the first knot
/// (R = R_0 exp(r), so the orientation stays a rotation); the reference COM uses the same scheme. Before the first
/// knot and after the last the posture is held.
class TrajectoryInterpolator {
 public:
  /// Throws std::invalid_argument for a null model, fewer than one knot, a wrong configuration size, times not
  /// increasing, an unknown `kind` (use hermite or spline), or, for "spline", a base rotation of more than
  /// 0.9 pi from the first knot (the rotation vector would wrap; use hermite).
  TrajectoryInterpolator(std::shared_ptr<const multibody::Model> model, std::vector<InterpolationKnot> knots,
                         const std::string& kind = "hermite");

  /// q (size nq, unit quaternion) and v (size nv, analytic; the floating base's body twist [w; R^T p']) at t.
  void Evaluate(double t, Eigen::VectorXd* q, Eigen::VectorXd* v) const;
  /// q at time t.
  Eigen::VectorXd Position(double t) const;
  /// The interpolated horizontal COM of the knots: the reference ZMP (thesis: the interpolated f_xy(q_t)).
  Eigen::Vector2d ReferenceZmp(double t) const;
  /// Soles on the ground at time t: those in contact at both ends of the segment (bits kLeftSoleContact...).
  int Contacts(double t) const;

  double start_time() const { return knots_.front().time; }
  double end_time() const { return knots_.back().time; }
  const std::vector<InterpolationKnot>& knots() const { return knots_; }

 private:
  // Channels: [base xyz, rotation vector (spline) or unused (hermite), joint coordinates..., com xy].
  Eigen::VectorXd Channels(double t, Eigen::VectorXd* rate) const;
  std::size_t Segment(double t) const;
  Eigen::VectorXd Assemble(double t, const Eigen::VectorXd& channels) const;

  std::shared_ptr<const multibody::Model> model_;
  std::vector<InterpolationKnot> knots_;
  bool spline_{false};
  int base_q_{-1};                 // index of the floating base's x in q, -1 without one
  Eigen::MatrixXd values_;         // knots x channels
  Eigen::MatrixXd second_;         // spline second derivatives, knots x channels
  std::vector<int> joint_q_;       // q index of each non-base coordinate channel
};

}  // namespace cairn::planning
