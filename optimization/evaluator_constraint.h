#pragma once

#include <memory>

#include "cairn/optimization/constraint.h"

namespace cairn::optimization {

/// A generic nonlinear constraint lb <= f(x) <= ub around any Evaluator, sharing its name, Jacobian pattern,
/// derivative source and (if any) Hessian.
class EvaluatorConstraint final : public Constraint {
 public:
  /// Throws std::invalid_argument if `evaluator` is null or the bounds do not match its outputs.
  EvaluatorConstraint(std::shared_ptr<const Evaluator> evaluator, const Eigen::Ref<const Eigen::VectorXd>& lower_bound,
                      const Eigen::Ref<const Eigen::VectorXd>& upper_bound);

  /// The wrapped function.
  const Evaluator& evaluator() const { return *evaluator_; }

 private:
  void DoEval(const Eigen::Ref<const Eigen::VectorXd>& x, Eigen::Ref<Eigen::VectorXd> y) const override;
  void DoEvalWithJacobian(const Eigen::Ref<const Eigen::VectorXd>& x, Eigen::Ref<Eigen::VectorXd> y,
                          Eigen::Ref<Eigen::VectorXd> jacobian_values) const override;
  void DoEvalHessian(const Eigen::Ref<const Eigen::VectorXd>& x, const Eigen::Ref<const Eigen::VectorXd>& weights,
                     Eigen::Ref<Eigen::VectorXd> hessian_values) const override;

  std::shared_ptr<const Evaluator> evaluator_;
};

}  // namespace cairn::optimization
