#include <cairn/planning/trajectory/scaled_evaluator.h>

#include <cmath>
#include <stdexcept>
#include <utility>

#include <cairn/common/number_text.h>

namespace cairn::planning {

namespace {
const optimization::Evaluator& Checked(const std::shared_ptr<const optimization::Evaluator>& function, double weight) {
  if (function == nullptr) throw std::invalid_argument("ScaledEvaluator: the evaluator is null");
  if (!(weight > 0.0) || !std::isfinite(weight)) {
    throw std::invalid_argument("ScaledEvaluator: weight " + FormatShort(weight) + " for '" + function->name() +
                                "' must be finite and positive");
  }
  return *function;
}
}  // namespace

ScaledEvaluator::ScaledEvaluator(std::shared_ptr<const optimization::Evaluator> function, double weight)
    : optimization::Evaluator(Checked(function, weight).name(), function->num_inputs(), function->num_outputs(),
                              function->jacobian_pattern(), function->jacobian_source()),
      function_(std::move(function)),
      weight_(weight) {
  if (function_->has_hessian()) DeclareHessianPattern(function_->hessian_pattern());
}

void ScaledEvaluator::DoEval(const Eigen::Ref<const Eigen::VectorXd>& x, Eigen::Ref<Eigen::VectorXd> y) const {
  function_->Eval(x, y);
  y *= weight_;
}

void ScaledEvaluator::DoEvalWithJacobian(const Eigen::Ref<const Eigen::VectorXd>& x, Eigen::Ref<Eigen::VectorXd> y,
                                         Eigen::Ref<Eigen::VectorXd> jacobian_values) const {
  function_->EvalWithJacobian(x, y, jacobian_values);
  y *= weight_;
  jacobian_values *= weight_;
}

void ScaledEvaluator::DoEvalHessian(const Eigen::Ref<const Eigen::VectorXd>& x,
                                    const Eigen::Ref<const Eigen::VectorXd>& weights,
                                    Eigen::Ref<Eigen::VectorXd> hessian_values) const {
  function_->EvalHessian(x, weight_ * weights, hessian_values);
}

}  // namespace cairn::planning
