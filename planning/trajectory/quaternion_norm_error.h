#pragma once

#include <cairn/optimization/evaluator.h>

namespace cairn::planning {

/// |quat|^2 - 1 for the floating base's four quaternion variables: with the evaluators reading quat / |quat|
/// (ConfigurationChart), this equality removes the free scale so the problem has isolated solutions. It is
/// quadratic, so its exact Hessian (2 I) is declared.
class QuaternionNormError final : public optimization::Evaluator {
 public:
  /// Four inputs (qw, qx, qy, qz), one output.
  QuaternionNormError();

 private:
  void DoEval(const Eigen::Ref<const Eigen::VectorXd>& x, Eigen::Ref<Eigen::VectorXd> y) const override;
  void DoEvalWithJacobian(const Eigen::Ref<const Eigen::VectorXd>& x, Eigen::Ref<Eigen::VectorXd> y,
                          Eigen::Ref<Eigen::VectorXd> jacobian_values) const override;
  void DoEvalHessian(const Eigen::Ref<const Eigen::VectorXd>& x, const Eigen::Ref<const Eigen::VectorXd>& weights,
                     Eigen::Ref<Eigen::VectorXd> hessian_values) const override;
};

}  // namespace cairn::planning
