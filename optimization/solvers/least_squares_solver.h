#pragma once

#include "cairn/optimization/solvers/solver.h"

namespace cairn::optimization {

/// Levenberg–Marquardt (or Gauss–Newton) for programs made of least-squares costs, with the sparse normal
/// equations (J'J + damping) factorised by CHOLMOD (SuiteSparse). Bounding boxes are enforced by projecting
/// every step; linear equality constraints A x = b by an augmented-Lagrangian outer loop whose penalty rows are
/// stacked under the residuals, so the normal equations keep one sparsity pattern that CHOLMOD analyses once.
///
/// Supported programs: at least one AddLeastSquaresCost, no other costs, and constraints that are bounding boxes
/// or LinearEqualityConstraints (CheckSupport names the first offending term otherwise).
///
/// Options (key "least_squares"): algorithm ("levenberg_marquardt" default, or "gauss_newton" with a
/// backtracking line search), max_iterations (integer, default 200, per outer iteration), gradient_tolerance
/// (projected-gradient infinity norm, default 1e-10), step_tolerance (relative, default 1e-12),
/// function_tolerance (relative decrease, default 1e-14), initial_damping (times max diag(J'J), default
/// 1e-4), constraint_tol (equality violation, default 1e-9), max_outer_iterations (integer, default 30).
/// Ranges (std::invalid_argument otherwise): the iteration counts >= 1, initial_damping > 0, the tolerances and
/// constraint_tol >= 0, every number finite.
///
/// The Marquardt damping scales diag(J'J), so the method is invariant to variable scaling. The equality
/// multipliers are reported in constraint_duals (Ipopt's sign convention); there are no bound duals.
class LeastSquaresSolver final : public Solver {
 public:
  /// Name "least_squares", options key "least_squares".
  LeastSquaresSolver();

  /// Always true: SuiteSparse is a required dependency of Cairn::optimization.
  bool available() const override { return true; }

 private:
  std::string DoCheckSupport(const MathematicalProgram& prog) const override;
  SolverResult DoSolve(const MathematicalProgram& prog, const Eigen::VectorXd& initial_guess,
                       const SolverOptions::OptionMap& options) const override;
};

}  // namespace cairn::optimization
