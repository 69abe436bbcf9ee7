#pragma once

#include "cairn/optimization/linear_constraint.h"

namespace cairn::optimization {

/// The constraint lb <= x <= ub on the bound variables. Solvers fold these into their variable bounds instead of
/// treating them as constraint rows.
class BoundingBoxConstraint final : public LinearConstraint {
 public:
  /// Throws std::invalid_argument if the bounds differ in size, are NaN or have lb > ub.
  BoundingBoxConstraint(const Eigen::Ref<const Eigen::VectorXd>& lower_bound,
                        const Eigen::Ref<const Eigen::VectorXd>& upper_bound);
};

}  // namespace cairn::optimization
