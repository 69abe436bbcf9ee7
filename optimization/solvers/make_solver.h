#pragma once

#include <memory>
#include <string>
#include <vector>

#include "cairn/optimization/solvers/solver.h"

namespace cairn::optimization {

/// Creates a solver from its configuration-file name: "ipopt", "least_squares", or "nlopt:<stages>" with NLopt
/// algorithm stages joined by '+' (e.g. "nlopt:SLSQP", "nlopt:ORIG_DIRECT+SLSQP", "nlopt:LN_COBYLA"). Throws
/// std::invalid_argument naming the bad value and listing the valid names.
std::unique_ptr<Solver> MakeSolver(const std::string& name);

/// Example names MakeSolver accepts, for messages and `--help` texts.
std::vector<std::string> SolverNameExamples();

}  // namespace cairn::optimization
