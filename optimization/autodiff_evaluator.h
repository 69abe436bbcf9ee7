#pragma once

#include <string>
#include <utility>
#include <vector>

// Eigen 3.4's AutoDiff module does not include Eigen/Core itself.
#include <Eigen/Core>
#include <unsupported/Eigen/AutoDiff>

#include "cairn/optimization/evaluator.h"

namespace cairn::optimization {

/// An Evaluator whose Jacobian comes from Eigen's forward-mode AutoDiffScalar, for functions written once
/// generically over the scalar type.
///
/// `Functor` must provide
/// `template <typename T> void operator()(const Eigen::Matrix<T, Eigen::Dynamic, 1>& x,
///                                        Eigen::Matrix<T, Eigen::Dynamic, 1>* y) const`
/// with y already sized to num_outputs. The declared pattern (dense by default) selects which derivatives are
/// reported; derivatives outside it are dropped, so declare every entry that can be nonzero (CheckGradients
/// finds omissions). Forward mode allocates a derivative vector per scalar operation: fine for small blocks,
/// but large or hot evaluators deserve analytic Jacobians.
template <typename Functor>
class AutoDiffEvaluator final : public Evaluator {
 public:
  /// Scalar type used for the derivative pass.
  using AutoDiff = Eigen::AutoDiffScalar<Eigen::VectorXd>;

  /// Dense Jacobian pattern.
  AutoDiffEvaluator(std::string name, int num_inputs, int num_outputs, Functor functor)
      : AutoDiffEvaluator(std::move(name), num_inputs, num_outputs, DensePattern(num_outputs, num_inputs),
                          std::move(functor)) {}

  /// Declared Jacobian pattern.
  AutoDiffEvaluator(std::string name, int num_inputs, int num_outputs, std::vector<SparsityEntry> pattern,
                    Functor functor)
      : Evaluator(std::move(name), num_inputs, num_outputs, std::move(pattern), DerivativeSource::kAutoDiff),
        functor_(std::move(functor)) {}

 private:
  void DoEval(const Eigen::Ref<const Eigen::VectorXd>& x, Eigen::Ref<Eigen::VectorXd> y) const override {
    // The functor takes plain vectors; per-thread copies keep the value path free of allocations.
    thread_local Eigen::VectorXd x_copy, y_copy;
    x_copy = x;
    y_copy.resize(num_outputs());
    functor_(x_copy, &y_copy);
    y = y_copy;
  }

  void DoEvalWithJacobian(const Eigen::Ref<const Eigen::VectorXd>& x, Eigen::Ref<Eigen::VectorXd> y,
                          Eigen::Ref<Eigen::VectorXd> jacobian_values) const override {
    const int n = num_inputs();
    Eigen::Matrix<AutoDiff, Eigen::Dynamic, 1> x_ad(n);
    for (int i = 0; i < n; ++i) x_ad[i] = AutoDiff(x[i], n, i);
    Eigen::Matrix<AutoDiff, Eigen::Dynamic, 1> y_ad(num_outputs());
    functor_(x_ad, &y_ad);
    for (int r = 0; r < num_outputs(); ++r) y[r] = y_ad[r].value();
    const std::vector<SparsityEntry>& pattern = jacobian_pattern();
    for (std::size_t k = 0; k < pattern.size(); ++k) {
      const auto& d = y_ad[pattern[k].row].derivatives();
      // An output that does not depend on x keeps an empty derivative vector.
      jacobian_values[static_cast<Eigen::Index>(k)] = d.size() == 0 ? 0.0 : d[pattern[k].col];
    }
  }

  Functor functor_;
};

}  // namespace cairn::optimization
