#pragma once

#include <Eigen/SparseCore>

#include "cairn/optimization/constraint.h"

namespace cairn::optimization {

/// The constraint lb <= A x <= ub with a sparse A. A's stored entries are the Jacobian pattern.
class LinearConstraint : public Constraint {
 public:
  /// Throws std::invalid_argument if A has a non-finite entry or the bounds do not match A's rows.
  LinearConstraint(const Eigen::SparseMatrix<double>& A, const Eigen::Ref<const Eigen::VectorXd>& lower_bound,
                   const Eigen::Ref<const Eigen::VectorXd>& upper_bound);

  /// The constraint matrix.
  const Eigen::SparseMatrix<double>& A() const { return A_; }

 protected:
  /// For subclasses that want their own name in messages.
  LinearConstraint(std::string name, const Eigen::SparseMatrix<double>& A,
                   const Eigen::Ref<const Eigen::VectorXd>& lower_bound,
                   const Eigen::Ref<const Eigen::VectorXd>& upper_bound);

 private:
  void DoEval(const Eigen::Ref<const Eigen::VectorXd>& x, Eigen::Ref<Eigen::VectorXd> y) const override;
  void DoEvalWithJacobian(const Eigen::Ref<const Eigen::VectorXd>& x, Eigen::Ref<Eigen::VectorXd> y,
                          Eigen::Ref<Eigen::VectorXd> jacobian_values) const override;
  void DoEvalHessian(const Eigen::Ref<const Eigen::VectorXd>& x, const Eigen::Ref<const Eigen::VectorXd>& weights,
                     Eigen::Ref<Eigen::VectorXd> hessian_values) const override;

  Eigen::SparseMatrix<double, Eigen::RowMajor> A_row_major_;
  Eigen::SparseMatrix<double> A_;
  Eigen::VectorXd values_;  // A's entries in Jacobian-pattern order.
};

}  // namespace cairn::optimization
