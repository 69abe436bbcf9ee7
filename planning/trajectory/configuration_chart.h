#pragma once

#include <vector>

#include <Eigen/Core>

#include <cairn/multibody/model.h>

namespace cairn::planning {

/// The coordinates the whole-body optimiser works in, and how derivatives reach them.
///
/// The decision variables of a waypoint are the model's configuration q (size nq), including the floating
/// base's position and its quaternion [qw, qx, qy, qz]. The multibody algorithms give Jacobians with respect to
/// tangent perturbations v (size nv: the base's body twist [ω; v], then the joints). The unit quaternion is
/// handled by normalisation plus a constraint: every evaluator reads the quaternion as quat / |quat| (so any
/// nonzero iterate of the solver is a valid pose and the functions are smooth in all four entries), and the
/// problem adds |quat|^2 = 1 per waypoint to remove the scale direction the normalisation leaves free. The chart
/// maps a tangent-space Jacobian to q: d/dp = d/dv_lin R^T, d/dquat = d/dω (2 / |quat|) G(n) with
/// G(n) = [-u, w I - [u]x] for n = (w, u) = quat / |quat|, joints unchanged.
///
/// A model without a floating joint gets the identity map. A floating joint other than the first joint (the
/// root) is rejected: the optimiser does not support several free bodies.
class ConfigurationChart {
 public:
  /// Throws std::invalid_argument if the model has a floating joint that is not joint 1 at q index 0.
  explicit ConfigurationChart(const multibody::Model& model);

  /// True if the model's root is a floating joint (q[0:3] position, q[3:7] quaternion).
  bool has_floating_base() const { return floating_; }

  /// Number of configuration coordinates.
  int nq() const { return nq_; }

  /// Number of velocity coordinates.
  int nv() const { return nv_; }

  /// q with the floating base's quaternion divided by its norm. Throws std::invalid_argument if the quaternion
  /// is zero or not finite (no pose corresponds to it).
  Eigen::VectorXd Normalized(const Eigen::Ref<const Eigen::VectorXd>& q) const;

  /// Maps a Jacobian with respect to tangent perturbations (rows x nv) at raw (unnormalised) q to the Jacobian
  /// with respect to q itself (rows x nq).
  Eigen::MatrixXd TangentToCoordinates(const Eigen::Ref<const Eigen::VectorXd>& q,
                                       const Eigen::Ref<const Eigen::MatrixXd>& J_v) const;

  /// The q columns a function of body `body`'s pose can depend on (the floating base and the coordinates of the
  /// joints from the root to the body), sorted: the structural sparsity of frame Jacobians in q.
  std::vector<int> CoordinatesMovingBody(const multibody::Model& model, int body) const;

  /// Indices in q of the revolute and prismatic joint coordinates (everything but the floating base).
  const std::vector<int>& joint_coordinates() const { return joint_q_; }

  /// For each entry of joint_coordinates(), its velocity index.
  const std::vector<int>& joint_velocities() const { return joint_v_; }

 private:
  bool floating_{false};
  int nq_{0};
  int nv_{0};
  std::vector<int> joint_q_;
  std::vector<int> joint_v_;
};

}  // namespace cairn::planning
