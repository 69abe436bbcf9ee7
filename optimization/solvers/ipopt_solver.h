#pragma once

#include "cairn/optimization/solvers/solver.h"

namespace cairn::optimization {

/// Ipopt (interior point, sparse) through a TNLP adapter over ProgramAssembly: the constraint Jacobian's
/// structure is reported once from the programme's declared patterns, the exact Lagrangian Hessian is used when
/// every term provides one and L-BFGS otherwise ("hessian_approximation" may override this).
///
/// Options (key "ipopt"): any registered Ipopt option by its Ipopt name, with its Ipopt type (integer, number
/// or string; an integer is accepted for a number). Unknown names and wrong types are rejected with the closest
/// valid names. Defaults that differ from Ipopt's: print_level = 0 and sb = "yes" (quiet). The options file
/// ./ipopt.opt is never read. One option is Cairn's, not Ipopt's: "least_squares_hessian" = "exact" (default:
/// J'J + sum_k r_k Hessian(r_k) for every least-squares cost, which needs the residuals' Hessians) or
/// "gauss-newton" (J'J alone, ProgramAssembly::LeastSquaresHessian::kGaussNewton), which lets Ipopt use an exact
/// Hessian mode when residuals have no second derivatives or when theirs are expensive.
///
/// Thread safety: Ipopt 3.11 as packaged by Debian (MUMPS sequential) crashes or hangs when two solves run at
/// once in one process, even with separate IpoptApplication objects. Every IpoptSolver::Solve therefore holds a
/// process-wide mutex for the whole solve: concurrent calls are safe and give correct answers, but run one
/// after another. Run Ipopt in separate processes for parallelism.
///
/// Status mapping: Solve_Succeeded and Solved_To_Acceptable_Level -> kSolved; Infeasible_Problem_Detected ->
/// kInfeasible; Diverging_Iterates -> kUnbounded; Maximum_Iterations_Exceeded -> kIterationLimit;
/// Maximum_CpuTime_Exceeded -> kTimeLimit; restoration, step-computation and invalid-number failures ->
/// kNumericalFailure; everything else -> kFailed. Duals follow Ipopt's convention (L = f + lambda' g).
class IpoptSolver final : public Solver {
 public:
  /// Name "ipopt", options key "ipopt".
  IpoptSolver();

  /// Always true: Ipopt is a required dependency of Cairn::optimization.
  bool available() const override { return true; }

 private:
  std::string DoCheckSupport(const MathematicalProgram& prog) const override;
  SolverResult DoSolve(const MathematicalProgram& prog, const Eigen::VectorXd& initial_guess,
                       const SolverOptions::OptionMap& options) const override;
};

}  // namespace cairn::optimization
