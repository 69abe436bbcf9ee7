#pragma once

#include <Eigen/SparseCore>

#include "cairn/optimization/evaluator.h"

namespace cairn::optimization {

/// The cost 1/2 x'Qx + b'x + c with a sparse symmetric Q, whose exact Hessian (Q's lower triangle) is
/// declared so that Ipopt can use second derivatives.
class QuadraticCost final : public Evaluator {
 public:
  /// Throws std::invalid_argument if Q is not square and symmetric, if sizes disagree, or if a value is not
  /// finite.
  QuadraticCost(const Eigen::SparseMatrix<double>& Q, const Eigen::Ref<const Eigen::VectorXd>& b, double c);

  /// The symmetric matrix Q.
  const Eigen::SparseMatrix<double>& Q() const { return Q_; }
  /// Linear coefficients b.
  const Eigen::VectorXd& b() const { return b_; }
  /// Constant term c.
  double c() const { return c_; }

 private:
  void DoEval(const Eigen::Ref<const Eigen::VectorXd>& x, Eigen::Ref<Eigen::VectorXd> y) const override;
  void DoEvalWithJacobian(const Eigen::Ref<const Eigen::VectorXd>& x, Eigen::Ref<Eigen::VectorXd> y,
                          Eigen::Ref<Eigen::VectorXd> jacobian_values) const override;
  void DoEvalHessian(const Eigen::Ref<const Eigen::VectorXd>& x, const Eigen::Ref<const Eigen::VectorXd>& weights,
                     Eigen::Ref<Eigen::VectorXd> hessian_values) const override;

  Eigen::SparseMatrix<double> Q_;
  Eigen::VectorXd b_;
  double c_;
  Eigen::VectorXd lower_values_;  // Q's lower triangle in Hessian-pattern order.
};

}  // namespace cairn::optimization
