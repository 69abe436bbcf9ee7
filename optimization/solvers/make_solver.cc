#include "cairn/optimization/solvers/make_solver.h"

#include <stdexcept>

#include "cairn/common/text_suggestions.h"
#include "cairn/optimization/solvers/ipopt_solver.h"
#include "cairn/optimization/solvers/least_squares_solver.h"
#include "cairn/optimization/solvers/nlopt_solver.h"

namespace cairn::optimization {

std::vector<std::string> SolverNameExamples() {
  return {"ipopt", "least_squares", "nlopt:SLSQP", "nlopt:ORIG_DIRECT", "nlopt:ORIG_DIRECT+SLSQP", "nlopt:COBYLA"};
}

std::unique_ptr<Solver> MakeSolver(const std::string& name) {
  if (name == "ipopt") return std::make_unique<IpoptSolver>();
  if (name == "least_squares") return std::make_unique<LeastSquaresSolver>();
  const std::string prefix = "nlopt:";
  if (name.rfind(prefix, 0) == 0) return std::make_unique<NloptSolver>(name.substr(prefix.size()));
  const std::vector<std::string> closest = ClosestNames(name, {"ipopt", "least_squares", "nlopt:SLSQP"}, 1);
  throw std::invalid_argument("MakeSolver: unknown solver '" + name + "'" +
                              (closest.empty() ? "" : " (did you mean '" + closest[0] + "'?)") +
                              "; valid names are 'ipopt', 'least_squares' and 'nlopt:<ALGORITHM>[+<ALGORITHM>...]', "
                              "e.g. " + QuotedList(SolverNameExamples()) + ".");
}

}  // namespace cairn::optimization
