#include "cairn/common/number_text.h"
#include "cairn/optimization/linear_cost.h"

#include <cmath>
#include <stdexcept>

namespace cairn::optimization {

LinearCost::LinearCost(const Eigen::Ref<const Eigen::VectorXd>& a, double b)
    : Evaluator("LinearCost", static_cast<int>(a.size()), 1, DensePattern(1, static_cast<int>(a.size())),
                DerivativeSource::kAnalytic),
      a_(a),
      b_(b) {
  if (!a_.allFinite() || !std::isfinite(b)) {
    throw std::invalid_argument("LinearCost: the coefficients a and the constant b must be finite; got b = " +
                                cairn::FormatShort(b) + " and a with a non-finite entry if b is finite.");
  }
  DeclareHessianPattern({});
}

void LinearCost::DoEval(const Eigen::Ref<const Eigen::VectorXd>& x, Eigen::Ref<Eigen::VectorXd> y) const {
  y[0] = a_.dot(x) + b_;
}

void LinearCost::DoEvalWithJacobian(const Eigen::Ref<const Eigen::VectorXd>& x, Eigen::Ref<Eigen::VectorXd> y,
                                    Eigen::Ref<Eigen::VectorXd> jacobian_values) const {
  y[0] = a_.dot(x) + b_;
  jacobian_values = a_;
}

void LinearCost::DoEvalHessian(const Eigen::Ref<const Eigen::VectorXd>&, const Eigen::Ref<const Eigen::VectorXd>&,
                               Eigen::Ref<Eigen::VectorXd>) const {}

}  // namespace cairn::optimization
