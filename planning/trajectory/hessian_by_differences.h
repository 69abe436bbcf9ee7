#pragma once

#include <vector>

#include <Eigen/Core>

#include <cairn/optimization/evaluator.h>

namespace cairn::planning {

/// The lower-triangle pattern over `columns` (sorted ascending): every (columns[i], columns[j]) with i >= j.
std::vector<optimization::SparsityEntry> LowerTrianglePattern(const std::vector<int>& columns);

/// sum_k weights(k) Hessian(f_k)(x) by central differences of `f`'s analytic Jacobian (step cbrt(eps) max(1, |x_j|)
/// per column, symmetrised), written in the order of `pattern` (a LowerTrianglePattern). This is how the
/// whole-body evaluators provide the Hessian of the Lagrangian that Ipopt's exact-Hessian mode asks for: the
/// kinematic second derivatives are not written out by hand, but the result is the Hessian to about 1e-6
/// relative, far closer than an L-BFGS model, and its cost is 2 |columns| Jacobian evaluations.
void HessianByDifferences(const optimization::Evaluator& f, const Eigen::Ref<const Eigen::VectorXd>& x,
                          const Eigen::Ref<const Eigen::VectorXd>& weights,
                          const std::vector<optimization::SparsityEntry>& pattern, Eigen::Ref<Eigen::VectorXd> values);

}  // namespace cairn::planning
