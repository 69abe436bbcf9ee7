#include "cairn/optimization/evaluator_constraint.h"

#include <stdexcept>

namespace cairn::optimization {

namespace {

const Evaluator& NotNull(const std::shared_ptr<const Evaluator>& evaluator) {
  if (evaluator == nullptr) {
    throw std::invalid_argument("EvaluatorConstraint: the evaluator is null; pass a constructed Evaluator.");
  }
  return *evaluator;
}

}  // namespace

EvaluatorConstraint::EvaluatorConstraint(std::shared_ptr<const Evaluator> evaluator,
                                         const Eigen::Ref<const Eigen::VectorXd>& lower_bound,
                                         const Eigen::Ref<const Eigen::VectorXd>& upper_bound)
    : Constraint(NotNull(evaluator).name(), NotNull(evaluator).num_inputs(), NotNull(evaluator).num_outputs(),
                 NotNull(evaluator).jacobian_pattern(), NotNull(evaluator).jacobian_source(), lower_bound,
                 upper_bound),
      evaluator_(std::move(evaluator)) {
  if (evaluator_->has_hessian()) DeclareHessianPattern(evaluator_->hessian_pattern());
}

void EvaluatorConstraint::DoEval(const Eigen::Ref<const Eigen::VectorXd>& x, Eigen::Ref<Eigen::VectorXd> y) const {
  evaluator_->Eval(x, y);
}

void EvaluatorConstraint::DoEvalWithJacobian(const Eigen::Ref<const Eigen::VectorXd>& x,
                                             Eigen::Ref<Eigen::VectorXd> y,
                                             Eigen::Ref<Eigen::VectorXd> jacobian_values) const {
  evaluator_->EvalWithJacobian(x, y, jacobian_values);
}

void EvaluatorConstraint::DoEvalHessian(const Eigen::Ref<const Eigen::VectorXd>& x,
                                        const Eigen::Ref<const Eigen::VectorXd>& weights,
                                        Eigen::Ref<Eigen::VectorXd> hessian_values) const {
  evaluator_->EvalHessian(x, weights, hessian_values);
}

}  // namespace cairn::optimization
