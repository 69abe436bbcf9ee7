#pragma once

#include "cairn/optimization/linear_constraint.h"

namespace cairn::optimization {

/// The constraint A x = b, a LinearConstraint with equal bounds. The least-squares solver accepts these
/// alongside its residual costs.
class LinearEqualityConstraint final : public LinearConstraint {
 public:
  /// Throws std::invalid_argument if b has a non-finite entry or does not match A's rows.
  LinearEqualityConstraint(const Eigen::SparseMatrix<double>& A, const Eigen::Ref<const Eigen::VectorXd>& b);

  /// Right-hand side b.
  const Eigen::VectorXd& b() const { return lower_bound(); }
};

}  // namespace cairn::optimization
