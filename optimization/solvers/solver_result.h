#pragma once

#include <string>

#include <Eigen/Core>

namespace cairn::optimization {

/// How a solve ended.
enum class SolutionStatus {
  kSolved,            ///< Converged to a (locally) optimal, feasible point within the tolerances.
  kInfeasible,        ///< Stopped at a point that violates the constraints (locally infeasible; not a proof).
  kUnbounded,         ///< The objective decreased without bound (iterates diverged).
  kIterationLimit,    ///< Hit the iteration or evaluation limit first.
  kTimeLimit,         ///< Hit the time limit first.
  kNumericalFailure,  ///< The solver could not make progress (round-off, failed step computation, NaN).
  kFailed,            ///< Any other failure; see SolverResult::message.
};

/// Returns e.g. "solved", "infeasible", "iteration limit".
const char* to_string(SolutionStatus status);

/// Everything a solver reports about one solve. Fields a solver does not provide stay empty (duals) or -1
/// (counts).
struct SolverResult {
  /// The solver's name, e.g. "ipopt" or "nlopt:LD_SLSQP".
  std::string solver_name;
  /// How the solve ended.
  SolutionStatus status{SolutionStatus::kFailed};
  /// Final decision vector (the best point the solver returned, also on failure).
  Eigen::VectorXd x;
  /// Objective at x.
  double objective{0.0};
  /// Largest violation of constraints and variable bounds at x.
  double constraint_violation{0.0};
  /// Multipliers of the stacked constraint rows (ProgramAssembly order) in the convention
  /// L = f + lambda' g, i.e. Ipopt's; empty if the solver has none.
  Eigen::VectorXd constraint_duals;
  /// Multipliers of the variable bounds as z_upper - z_lower (positive at an active upper bound); empty if the
  /// solver has none.
  Eigen::VectorXd bound_duals;
  /// Iterations (Ipopt, least squares) or -1.
  int iterations{-1};
  /// Objective evaluations (NLopt) or -1.
  int evaluations{-1};
  /// Wall-clock time of the whole solve, including setting the problem up.
  double wall_time_seconds{0.0};
  /// The solver's own account of the ending, for logs and error messages.
  std::string message;

  /// True if status == kSolved.
  bool is_success() const { return status == SolutionStatus::kSolved; }
};

}  // namespace cairn::optimization
