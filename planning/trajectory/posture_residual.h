#pragma once

#include <vector>

#include <Eigen/Core>

#include <cairn/optimization/evaluator.h>

namespace cairn::planning {

/// q_i - q_nominal_i over the selected coordinates of a configuration (linear; empty Hessian): the posture
/// regularisation that makes inverse kinematics of a redundant robot well posed.
class PostureResidual final : public optimization::Evaluator {
 public:
  /// `coordinates` index into q (size nq); throws std::invalid_argument for an index outside [0, nq) or a
  /// nominal of the wrong size.
  PostureResidual(int nq, const std::vector<int>& coordinates, const Eigen::VectorXd& nominal);

 private:
  void DoEval(const Eigen::Ref<const Eigen::VectorXd>& x, Eigen::Ref<Eigen::VectorXd> y) const override;
  void DoEvalWithJacobian(const Eigen::Ref<const Eigen::VectorXd>& x, Eigen::Ref<Eigen::VectorXd> y,
                          Eigen::Ref<Eigen::VectorXd> jacobian_values) const override;
  void DoEvalHessian(const Eigen::Ref<const Eigen::VectorXd>& x, const Eigen::Ref<const Eigen::VectorXd>& weights,
                     Eigen::Ref<Eigen::VectorXd> hessian_values) const override;

  std::vector<int> coordinates_;
  Eigen::VectorXd nominal_;
};

}  // namespace cairn::planning
