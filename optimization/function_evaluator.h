#pragma once

#include <functional>
#include <string>
#include <vector>

#include "cairn/optimization/evaluator.h"

namespace cairn::optimization {

/// An Evaluator made from callables, for costs and constraints that do not deserve their own class.
///
/// With a Jacobian callable the derivatives are analytic; without one they come from central finite
/// differences over the declared pattern (dense if none is given). An optional Hessian callable with its
/// lower-triangle pattern lets Ipopt use exact second derivatives.
class FunctionEvaluator final : public Evaluator {
 public:
  /// Computes y = f(x).
  using ValueFunction = std::function<void(const Eigen::Ref<const Eigen::VectorXd>& x, Eigen::Ref<Eigen::VectorXd> y)>;
  /// Computes y = f(x) and the Jacobian values in pattern order.
  using JacobianFunction = std::function<void(const Eigen::Ref<const Eigen::VectorXd>& x,
                                              Eigen::Ref<Eigen::VectorXd> y, Eigen::Ref<Eigen::VectorXd> values)>;
  /// Computes sum_k w_k Hessian(f_k) in lower-triangle pattern order.
  using HessianFunction =
      std::function<void(const Eigen::Ref<const Eigen::VectorXd>& x, const Eigen::Ref<const Eigen::VectorXd>& w,
                         Eigen::Ref<Eigen::VectorXd> values)>;

  /// Value only; the Jacobian is dense and computed by central finite differences.
  FunctionEvaluator(std::string name, int num_inputs, int num_outputs, ValueFunction value);

  /// Value and (if `jacobian` is non-empty) analytic Jacobian over `jacobian_pattern`; an empty `jacobian`
  /// means finite differences over that pattern. A non-empty `hessian` needs `hessian_pattern` (lower
  /// triangle).
  FunctionEvaluator(std::string name, int num_inputs, int num_outputs, std::vector<SparsityEntry> jacobian_pattern,
                    ValueFunction value, JacobianFunction jacobian, std::vector<SparsityEntry> hessian_pattern = {},
                    HessianFunction hessian = {});

 private:
  void DoEval(const Eigen::Ref<const Eigen::VectorXd>& x, Eigen::Ref<Eigen::VectorXd> y) const override;
  void DoEvalWithJacobian(const Eigen::Ref<const Eigen::VectorXd>& x, Eigen::Ref<Eigen::VectorXd> y,
                          Eigen::Ref<Eigen::VectorXd> jacobian_values) const override;
  void DoEvalHessian(const Eigen::Ref<const Eigen::VectorXd>& x, const Eigen::Ref<const Eigen::VectorXd>& weights,
                     Eigen::Ref<Eigen::VectorXd> hessian_values) const override;

  ValueFunction value_;
  JacobianFunction jacobian_;
  HessianFunction hessian_;
};

}  // namespace cairn::optimization
