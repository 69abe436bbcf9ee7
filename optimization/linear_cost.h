#pragma once

#include "cairn/optimization/evaluator.h"

namespace cairn::optimization {

/// The cost a'x + b. Its Hessian is declared (empty), so it never blocks Ipopt's exact-Hessian mode.
class LinearCost final : public Evaluator {
 public:
  /// Throws std::invalid_argument if `a` or `b` is not finite.
  LinearCost(const Eigen::Ref<const Eigen::VectorXd>& a, double b);

  /// Coefficients a.
  const Eigen::VectorXd& a() const { return a_; }
  /// Constant term b.
  double b() const { return b_; }

 private:
  void DoEval(const Eigen::Ref<const Eigen::VectorXd>& x, Eigen::Ref<Eigen::VectorXd> y) const override;
  void DoEvalWithJacobian(const Eigen::Ref<const Eigen::VectorXd>& x, Eigen::Ref<Eigen::VectorXd> y,
                          Eigen::Ref<Eigen::VectorXd> jacobian_values) const override;
  void DoEvalHessian(const Eigen::Ref<const Eigen::VectorXd>& x, const Eigen::Ref<const Eigen::VectorXd>& weights,
                     Eigen::Ref<Eigen::VectorXd> hessian_values) const override;

  Eigen::VectorXd a_;
  double b_;
};

}  // namespace cairn::optimization
