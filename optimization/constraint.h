#pragma once

#include <string>
#include <vector>

#include "cairn/optimization/evaluator.h"

namespace cairn::optimization {

/// An Evaluator with bounds: the constraint lb <= f(x) <= ub, row by row. Equality rows have lb == ub;
/// one-sided rows use -infinity or +infinity.
///
/// Subclasses: LinearConstraint (and LinearEqualityConstraint), BoundingBoxConstraint, and
/// EvaluatorConstraint, which turns any Evaluator into a nonlinear constraint.
class Constraint : public Evaluator {
 public:
  ~Constraint() override;

  /// Lower bounds, one per output.
  const Eigen::VectorXd& lower_bound() const { return lower_bound_; }
  /// Upper bounds, one per output.
  const Eigen::VectorXd& upper_bound() const { return upper_bound_; }

  /// Largest violation max(lb - y, y - ub, 0) over the rows of y = f(x).
  double Violation(const Eigen::Ref<const Eigen::VectorXd>& x) const;

 protected:
  /// Checks that both bounds have num_outputs entries, are not NaN and satisfy lb <= ub; throws
  /// std::invalid_argument naming the constraint and the offending row otherwise.
  Constraint(std::string name, int num_inputs, int num_outputs, std::vector<SparsityEntry> jacobian_pattern,
             DerivativeSource jacobian_source, const Eigen::Ref<const Eigen::VectorXd>& lower_bound,
             const Eigen::Ref<const Eigen::VectorXd>& upper_bound);

 private:
  Eigen::VectorXd lower_bound_;
  Eigen::VectorXd upper_bound_;
};

}  // namespace cairn::optimization
