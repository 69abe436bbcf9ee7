#include "cairn/optimization/linear_constraint.h"

#include <stdexcept>

namespace cairn::optimization {

namespace {

std::vector<SparsityEntry> RowMajorPattern(const Eigen::SparseMatrix<double, Eigen::RowMajor>& A) {
  std::vector<SparsityEntry> pattern;
  pattern.reserve(static_cast<std::size_t>(A.nonZeros()));
  for (int row = 0; row < A.outerSize(); ++row) {
    for (Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator it(A, row); it; ++it) {
      pattern.push_back({row, static_cast<int>(it.col())});
    }
  }
  return pattern;
}

Eigen::SparseMatrix<double, Eigen::RowMajor> Compressed(const Eigen::SparseMatrix<double>& A) {
  Eigen::SparseMatrix<double, Eigen::RowMajor> row_major = A;
  row_major.makeCompressed();
  return row_major;
}

}  // namespace

LinearConstraint::LinearConstraint(const Eigen::SparseMatrix<double>& A,
                                   const Eigen::Ref<const Eigen::VectorXd>& lower_bound,
                                   const Eigen::Ref<const Eigen::VectorXd>& upper_bound)
    : LinearConstraint("LinearConstraint", A, lower_bound, upper_bound) {}

LinearConstraint::LinearConstraint(std::string name, const Eigen::SparseMatrix<double>& A,
                                   const Eigen::Ref<const Eigen::VectorXd>& lower_bound,
                                   const Eigen::Ref<const Eigen::VectorXd>& upper_bound)
    : Constraint(std::move(name), static_cast<int>(A.cols()), static_cast<int>(A.rows()),
                 RowMajorPattern(Compressed(A)), DerivativeSource::kAnalytic, lower_bound, upper_bound),
      A_row_major_(Compressed(A)),
      A_(A) {
  values_ = Eigen::Map<const Eigen::VectorXd>(A_row_major_.valuePtr(), A_row_major_.nonZeros());
  if (!values_.allFinite()) {
    throw std::invalid_argument("Constraint '" + this->name() +
                                "': the matrix A has a non-finite entry; every coefficient must be finite.");
  }
  DeclareHessianPattern({});
}

void LinearConstraint::DoEval(const Eigen::Ref<const Eigen::VectorXd>& x, Eigen::Ref<Eigen::VectorXd> y) const {
  y.noalias() = A_row_major_ * x;
}

void LinearConstraint::DoEvalWithJacobian(const Eigen::Ref<const Eigen::VectorXd>& x, Eigen::Ref<Eigen::VectorXd> y,
                                          Eigen::Ref<Eigen::VectorXd> jacobian_values) const {
  y.noalias() = A_row_major_ * x;
  jacobian_values = values_;
}

void LinearConstraint::DoEvalHessian(const Eigen::Ref<const Eigen::VectorXd>&,
                                     const Eigen::Ref<const Eigen::VectorXd>&, Eigen::Ref<Eigen::VectorXd>) const {}

}  // namespace cairn::optimization
