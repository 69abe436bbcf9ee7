#include <cairn/planning/trajectory/quaternion_norm_error.h>

namespace cairn::planning {

QuaternionNormError::QuaternionNormError()
    : optimization::Evaluator("unit_quaternion", 4, 1, DensePattern(1, 4), optimization::DerivativeSource::kAnalytic) {
  DeclareHessianPattern({{0, 0}, {1, 1}, {2, 2}, {3, 3}});
}

void QuaternionNormError::DoEval(const Eigen::Ref<const Eigen::VectorXd>& x, Eigen::Ref<Eigen::VectorXd> y) const {
  y(0) = x.squaredNorm() - 1.0;
}

void QuaternionNormError::DoEvalWithJacobian(const Eigen::Ref<const Eigen::VectorXd>& x, Eigen::Ref<Eigen::VectorXd> y,
                                             Eigen::Ref<Eigen::VectorXd> jacobian_values) const {
  y(0) = x.squaredNorm() - 1.0;
  jacobian_values = 2.0 * x;
}

void QuaternionNormError::DoEvalHessian(const Eigen::Ref<const Eigen::VectorXd>&,
                                        const Eigen::Ref<const Eigen::VectorXd>& weights,
                                        Eigen::Ref<Eigen::VectorXd> hessian_values) const {
  hessian_values.setConstant(2.0 * weights(0));
}

}  // namespace cairn::planning
