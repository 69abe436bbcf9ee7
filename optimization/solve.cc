#include "cairn/optimization/solve.h"

#include "cairn/optimization/solvers/ipopt_solver.h"
#include "cairn/optimization/solvers/least_squares_solver.h"

namespace cairn::optimization {

std::unique_ptr<Solver> ChooseSolver(const MathematicalProgram& prog) {
  auto least_squares = std::make_unique<LeastSquaresSolver>();
  if (least_squares->CheckSupport(prog).empty()) return least_squares;
  return std::make_unique<IpoptSolver>();
}

SolverResult Solve(const MathematicalProgram& prog, const SolverOptions& options) {
  return ChooseSolver(prog)->Solve(prog, prog.initial_guess(), options);
}

}  // namespace cairn::optimization
