#include "cairn/common/number_text.h"
#include "cairn/optimization/quadratic_cost.h"

#include <cmath>
#include <stdexcept>

namespace cairn::optimization {

namespace {

int CheckedSize(const Eigen::SparseMatrix<double>& Q, const Eigen::Ref<const Eigen::VectorXd>& b) {
  if (Q.rows() != Q.cols() || Q.rows() != b.size()) {
    throw std::invalid_argument("QuadraticCost: Q is " + cairn::FormatShort(Q.rows()) + " x " + cairn::FormatShort(Q.cols()) +
                                " and b has size " + cairn::FormatShort(b.size()) +
                                "; Q must be square with as many rows as b has entries.");
  }
  return static_cast<int>(b.size());
}

}  // namespace

QuadraticCost::QuadraticCost(const Eigen::SparseMatrix<double>& Q, const Eigen::Ref<const Eigen::VectorXd>& b,
                             double c)
    : Evaluator("QuadraticCost", CheckedSize(Q, b), 1, DensePattern(1, CheckedSize(Q, b)),
                DerivativeSource::kAnalytic),
      Q_(Q),
      b_(b),
      c_(c) {
  Q_.makeCompressed();
  const Eigen::SparseMatrix<double> transpose = Q_.transpose();
  const double asymmetry = (Q_ - transpose).cwiseAbs().sum();
  if (!std::isfinite(asymmetry) || asymmetry > 1e-12 * (1.0 + Q_.cwiseAbs().sum())) {
    throw std::invalid_argument("QuadraticCost: Q is not symmetric (sum |Q - Q'| = " + cairn::FormatShort(asymmetry) +
                                ") or has non-finite entries; pass (Q + Q')/2 for the same cost.");
  }
  if (!b_.allFinite() || !std::isfinite(c)) {
    throw std::invalid_argument("QuadraticCost: b and c must be finite; got c = " + cairn::FormatShort(c) + ".");
  }
  std::vector<SparsityEntry> pattern;
  std::vector<double> values;
  for (int col = 0; col < Q_.outerSize(); ++col) {
    for (Eigen::SparseMatrix<double>::InnerIterator it(Q_, col); it; ++it) {
      if (it.row() >= it.col()) {
        pattern.push_back({static_cast<int>(it.row()), static_cast<int>(it.col())});
        values.push_back(it.value());
      }
    }
  }
  lower_values_ = Eigen::Map<const Eigen::VectorXd>(values.data(), static_cast<Eigen::Index>(values.size()));
  DeclareHessianPattern(std::move(pattern));
}

void QuadraticCost::DoEval(const Eigen::Ref<const Eigen::VectorXd>& x, Eigen::Ref<Eigen::VectorXd> y) const {
  // x'Qx by a loop over the nonzeros: the expression Q_ * x would allocate a temporary on every call.
  double quadratic = 0.0;
  for (int col = 0; col < Q_.outerSize(); ++col) {
    for (Eigen::SparseMatrix<double>::InnerIterator it(Q_, col); it; ++it) {
      quadratic += x[it.row()] * it.value() * x[col];
    }
  }
  y[0] = 0.5 * quadratic + b_.dot(x) + c_;
}

void QuadraticCost::DoEvalWithJacobian(const Eigen::Ref<const Eigen::VectorXd>& x, Eigen::Ref<Eigen::VectorXd> y,
                                       Eigen::Ref<Eigen::VectorXd> jacobian_values) const {
  jacobian_values.noalias() = Q_ * x;
  y[0] = 0.5 * x.dot(jacobian_values) + b_.dot(x) + c_;
  jacobian_values += b_;
}

void QuadraticCost::DoEvalHessian(const Eigen::Ref<const Eigen::VectorXd>&,
                                  const Eigen::Ref<const Eigen::VectorXd>& weights,
                                  Eigen::Ref<Eigen::VectorXd> hessian_values) const {
  hessian_values = weights[0] * lower_values_;
}

}  // namespace cairn::optimization
