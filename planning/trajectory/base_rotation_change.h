#pragma once

#include <cairn/optimization/evaluator.h>

namespace cairn::planning {

/// The change of the floating base's orientation between two consecutive waypoints as a least-squares residual:
/// r = 2 (quat_b - quat_a) over the two waypoints' quaternion variables [qw, qx, qy, qz] (inputs: quat_a then
/// quat_b, 8; outputs: 4). For unit quaternions in the same hemisphere (quat_a . quat_b >= 0) |r| = 4 sin(theta / 4)
/// for the rotation angle theta between the two orientations, so |r|^2 = theta^2 (1 + O(theta^2)): weighted, it
/// is a smoothness cost in rad^2 on the waist's roll, pitch and yaw together. It is linear in the variables, so
/// its Jacobian is constant and its Hessian is empty (the least-squares cost's J'J is exact); the hemisphere is
/// the caller's to keep (TrajectoryProblem's warm start picks each quaternion's sign continuous with the one
/// before, and a solver's continuous iterates cannot flip a sign while |quat| = 1 is enforced).
class BaseRotationChange final : public optimization::Evaluator {
 public:
  BaseRotationChange();

 private:
  void DoEval(const Eigen::Ref<const Eigen::VectorXd>& x, Eigen::Ref<Eigen::VectorXd> y) const override;
  void DoEvalWithJacobian(const Eigen::Ref<const Eigen::VectorXd>& x, Eigen::Ref<Eigen::VectorXd> y,
                          Eigen::Ref<Eigen::VectorXd> jacobian_values) const override;
  void DoEvalHessian(const Eigen::Ref<const Eigen::VectorXd>& x, const Eigen::Ref<const Eigen::VectorXd>& weights,
                     Eigen::Ref<Eigen::VectorXd> hessian_values) const override;
};

}  // namespace cairn::planning
