#pragma once

#include <memory>

#include <cairn/optimization/evaluator.h>

namespace cairn::planning {

/// weight * f(x) for another evaluator f, with f's pattern and derivative source (and Hessian, when f has one):
/// how InverseKinematics weighs its least-squares residuals against each other.
class ScaledEvaluator final : public optimization::Evaluator {
 public:
  /// Throws std::invalid_argument for a null evaluator or a weight that is not finite and positive.
  ScaledEvaluator(std::shared_ptr<const optimization::Evaluator> function, double weight);

  /// The weight.
  double weight() const { return weight_; }

 private:
  void DoEval(const Eigen::Ref<const Eigen::VectorXd>& x, Eigen::Ref<Eigen::VectorXd> y) const override;
  void DoEvalWithJacobian(const Eigen::Ref<const Eigen::VectorXd>& x, Eigen::Ref<Eigen::VectorXd> y,
                          Eigen::Ref<Eigen::VectorXd> jacobian_values) const override;
  void DoEvalHessian(const Eigen::Ref<const Eigen::VectorXd>& x, const Eigen::Ref<const Eigen::VectorXd>& weights,
                     Eigen::Ref<Eigen::VectorXd> hessian_values) const override;

  std::shared_ptr<const optimization::Evaluator> function_;
  double weight_;
};

}  // namespace cairn::planning
