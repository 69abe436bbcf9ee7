// Cairn::optimization: a tiny quadratic program solved by Ipopt, whose library only Cairn's links.
//   minimise (x - 1)^2 + (y - 2)^2  subject to  x + y <= 2   ->   x = 0.5, y = 1.5, cost 0.5
#include <cmath>
#include <cstdio>
#include <limits>

#include <cairn/optimization/mathematical_program.h>
#include <cairn/optimization/solvers/ipopt_solver.h>

int main() {
  using namespace cairn::optimization;
  MathematicalProgram prog;
  const DecisionVariables xy = prog.NewContinuousVariables(2, "xy");
  Eigen::SparseMatrix<double> Q(2, 2);
  Q.insert(0, 0) = 2.0;
  Q.insert(1, 1) = 2.0;
  prog.AddQuadraticCost(Q, Eigen::Vector2d(-2.0, -4.0), 5.0, xy);
  Eigen::SparseMatrix<double> A(1, 2);
  A.insert(0, 0) = 1.0;
  A.insert(0, 1) = 1.0;
  prog.AddLinearConstraint(A, Eigen::VectorXd::Constant(1, -std::numeric_limits<double>::infinity()),
                           Eigen::VectorXd::Constant(1, 2.0), xy);
  const IpoptSolver solver;
  if (!solver.available()) {
    std::printf("consumer optimization: Ipopt is not available\n");
    return 1;
  }
  const SolverResult result = solver.Solve(prog);
  std::printf("consumer optimization: %s, x = (%.6f, %.6f), cost %.6f\n", result.is_success() ? "solved" : "failed",
              result.x[0], result.x[1], result.objective);
  const bool right = result.is_success() && std::abs(result.x[0] - 0.5) < 1e-6 &&
                     std::abs(result.x[1] - 1.5) < 1e-6 && std::abs(result.objective - 0.5) < 1e-6;
  return right ? 0 : 1;
}
