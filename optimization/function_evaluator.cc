#include "cairn/optimization/function_evaluator.h"

#include <stdexcept>

namespace cairn::optimization {

FunctionEvaluator::FunctionEvaluator(std::string name, int num_inputs, int num_outputs, ValueFunction value)
    : FunctionEvaluator(std::move(name), num_inputs, num_outputs, DensePattern(num_outputs, num_inputs),
                        std::move(value), JacobianFunction{}) {}

FunctionEvaluator::FunctionEvaluator(std::string name, int num_inputs, int num_outputs,
                                     std::vector<SparsityEntry> jacobian_pattern, ValueFunction value,
                                     JacobianFunction jacobian, std::vector<SparsityEntry> hessian_pattern,
                                     HessianFunction hessian)
    : Evaluator(std::move(name), num_inputs, num_outputs, std::move(jacobian_pattern),
                jacobian ? DerivativeSource::kAnalytic : DerivativeSource::kFiniteDifference),
      value_(std::move(value)),
      jacobian_(std::move(jacobian)),
      hessian_(std::move(hessian)) {
  if (!value_) {
    throw std::invalid_argument("FunctionEvaluator '" + this->name() +
                                "': the value function is empty; pass a callable that computes y = f(x).");
  }
  if (hessian_) {
    DeclareHessianPattern(std::move(hessian_pattern));
  } else if (!hessian_pattern.empty()) {
    throw std::invalid_argument("FunctionEvaluator '" + this->name() +
                                "': a Hessian pattern was given without a Hessian function; pass both or neither.");
  }
}

void FunctionEvaluator::DoEval(const Eigen::Ref<const Eigen::VectorXd>& x, Eigen::Ref<Eigen::VectorXd> y) const {
  value_(x, y);
}

void FunctionEvaluator::DoEvalWithJacobian(const Eigen::Ref<const Eigen::VectorXd>& x,
                                           Eigen::Ref<Eigen::VectorXd> y,
                                           Eigen::Ref<Eigen::VectorXd> jacobian_values) const {
  if (jacobian_) {
    jacobian_(x, y, jacobian_values);
  } else {
    FiniteDifferenceJacobian(x, y, jacobian_values);
  }
}

void FunctionEvaluator::DoEvalHessian(const Eigen::Ref<const Eigen::VectorXd>& x,
                                      const Eigen::Ref<const Eigen::VectorXd>& weights,
                                      Eigen::Ref<Eigen::VectorXd> hessian_values) const {
  hessian_(x, weights, hessian_values);
}

}  // namespace cairn::optimization
