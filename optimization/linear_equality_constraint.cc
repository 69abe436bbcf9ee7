#include "cairn/optimization/linear_equality_constraint.h"

#include <stdexcept>

namespace cairn::optimization {

namespace {

const Eigen::Ref<const Eigen::VectorXd>& CheckedRightHandSide(const Eigen::Ref<const Eigen::VectorXd>& b) {
  if (!b.allFinite()) {
    throw std::invalid_argument(
        "LinearEqualityConstraint: the right-hand side b has a non-finite entry; an equality needs finite values "
        "(use LinearConstraint with infinite bounds for one-sided rows).");
  }
  return b;
}

}  // namespace

LinearEqualityConstraint::LinearEqualityConstraint(const Eigen::SparseMatrix<double>& A,
                                                   const Eigen::Ref<const Eigen::VectorXd>& b)
    : LinearConstraint("LinearEqualityConstraint", A, CheckedRightHandSide(b), b) {}

}  // namespace cairn::optimization
