#pragma once

#include <memory>
#include <string>

#include <Eigen/Core>

#include "cairn/optimization/mathematical_program.h"

namespace cairn::optimization::test {

/// A program with its known optimum, for solver tests.
struct TestProblem {
  std::string name;
  std::unique_ptr<MathematicalProgram> prog;
  DecisionVariables x;
  double optimal_cost{0.0};
  Eigen::VectorXd optimal_x;  // empty if only the cost is known
};

/// Hock–Schittkowski 71 (Ipopt's HS071): analytic Jacobians and Hessians. f* = 17.0140173.
TestProblem MakeHs071();
/// HS6: (1 - x0)^2 s.t. 10 (x1 - x0^2) = 0, constraint Jacobian by finite differences. f* = 0 at (1, 1).
TestProblem MakeHs006();
/// HS35: QuadraticCost + LinearConstraint + x >= 0. f* = 1/9 at (4/3, 7/9, 4/9).
TestProblem MakeHs035();
/// HS100: 7 variables, 4 nonlinear inequalities, everything by AutoDiffEvaluator. f* = 680.6300573.
TestProblem MakeHs100();
/// Rosenbrock n = 2 from (-1.2, 1), one analytic scalar cost (with Hessian). f* = 0 at (1, 1).
TestProblem MakeRosenbrock2();
/// Chained Rosenbrock with n variables as least-squares residuals 10 (x_{i+1} - x_i^2), 1 - x_i (sparse analytic
/// Jacobians), from x = 0. f* = 0 at x = 1.
TestProblem MakeChainedRosenbrock(int n);
/// The sparse chain: min sum (x_i - 2)^2 s.t. x_i^2 + x_{i+1}^2 = 2 (n - 1 bindings of one evaluator with analytic
/// Jacobian and Hessian), x >= 0, n even, from x = 0.5. f* = n at x = 1.
TestProblem MakeSparseChain(int n);

}  // namespace cairn::optimization::test
