#pragma once

#include <vector>

#include <Eigen/Core>

#include <cairn/optimization/evaluator.h>

namespace cairn::planning {

/// The lower-triangle pattern over `columns` (sorted ascending): every (columns[i], columns[j]) with i >= j.
std::vector<optimization::SparsityEntry> LowerTrianglePattern(const std::vector<int>& columns);

/// How HessianByDifferences differences the Jacobian.
enum class DifferenceScheme {
  /// (g(x + h e_j) - g(x)) / h with h = sqrt(eps) max(1, |x_j|): |columns| + 1 Jacobian evaluations, truncation and
  /// rounding errors both about 1e-8 relative, for Jacobians that are smooth to rounding (the kinematic terms).
  kForward,
  /// (g(x + h e_j) - g(x - h e_j)) / 2h with h = cbrt(eps) max(1, |x_j|): 2 |columns| evaluations, about 1e-6
  /// relative, and the larger step averages out a Jacobian that is only smooth to an iterative solver's tolerance
  /// (the signed distances of CollisionWorld), which the forward step would amplify.
  kCentral,
};

/// sum_k weights(k) Hessian(f_k)(x) by differences of `f`'s analytic Jacobian (per column, symmetrised), written in
/// the order of `pattern` (a LowerTrianglePattern). This is how the whole-body evaluators provide the Hessian of the
/// Lagrangian that Ipopt's exact-Hessian mode asks for: the kinematic second derivatives are not written out by
/// hand, but the result is far closer to the Hessian than an L-BFGS model.
void HessianByDifferences(const optimization::Evaluator& f, const Eigen::Ref<const Eigen::VectorXd>& x,
                          const Eigen::Ref<const Eigen::VectorXd>& weights,
                          const std::vector<optimization::SparsityEntry>& pattern, Eigen::Ref<Eigen::VectorXd> values,
                          DifferenceScheme scheme = DifferenceScheme::kForward);

}  // namespace cairn::planning
