#pragma once

#include <memory>

#include "cairn/optimization/mathematical_program.h"
#include "cairn/optimization/solvers/solver.h"

namespace cairn::optimization {

/// The solver Solve(prog) would use: LeastSquaresSolver when the program is made of least-squares costs with
/// at most bounding boxes and linear equalities, IpoptSolver otherwise (it handles any smooth program and is
/// sparse). NLopt is never chosen implicitly: its algorithms suit particular problem shapes, so ask by name.
std::unique_ptr<Solver> ChooseSolver(const MathematicalProgram& prog);

/// Solves `prog` from its initial guess with ChooseSolver(prog) and `options`.
SolverResult Solve(const MathematicalProgram& prog, const SolverOptions& options = SolverOptions());

}  // namespace cairn::optimization
