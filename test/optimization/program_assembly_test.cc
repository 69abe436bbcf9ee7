#include "cairn/optimization/program_assembly.h"

#include <limits>
#include <set>

#include <gtest/gtest.h>

#include "cairn/optimization/function_evaluator.h"
#include "test_problems.h"

namespace cairn::optimization {
namespace {

using Eigen::Ref;
using Eigen::VectorXd;
constexpr double kInf = std::numeric_limits<double>::infinity();

TEST(ProgramAssemblyTest, StacksRowsAndMapsJacobianEntriesToProgramVariables) {
  MathematicalProgram prog;
  const auto x = prog.NewContinuousVariables(4, "x");
  prog.AddBoundingBoxConstraint(-1.0, 1.0, x.Segment(0, 2));
  Eigen::SparseMatrix<double> A(2, 2);
  A.insert(0, 0) = 1.0;
  A.insert(1, 1) = 3.0;
  prog.AddLinearConstraint(A, Eigen::Vector2d(0, -kInf), Eigen::Vector2d(1, 2), x.Segment(2, 2));
  auto product = std::make_shared<FunctionEvaluator>(
      "product", 2, 1, std::vector<SparsityEntry>{{0, 0}, {0, 1}},
      [](const Ref<const VectorXd>& v, Ref<VectorXd> y) { y[0] = v[0] * v[1]; },
      [](const Ref<const VectorXd>& v, Ref<VectorXd> y, Ref<VectorXd> j) {
        y[0] = v[0] * v[1];
        j << v[1], v[0];
      });
  // Bound to (x3, x0): local column 0 is program variable 3.
  prog.AddConstraint(product, Eigen::Matrix<double, 1, 1>(1.0), Eigen::Matrix<double, 1, 1>(1.0),
                     DecisionVariables::Concatenate({x.Element(3), x.Element(0)}));
  ProgramAssembly assembly(prog);
  EXPECT_EQ(assembly.num_vars(), 4);
  EXPECT_EQ(assembly.num_constraints(), 3);
  EXPECT_EQ(assembly.variable_lower_bounds(), Eigen::Vector4d(-1, -1, -kInf, -kInf));
  EXPECT_EQ(assembly.constraint_upper_bounds(), Eigen::Vector3d(1, 2, 1));
  EXPECT_EQ(assembly.constraint_row_offset(1), 2);
  EXPECT_EQ(assembly.jacobian_rows(), (std::vector<int>{0, 1, 2, 2}));
  EXPECT_EQ(assembly.jacobian_cols(), (std::vector<int>{2, 3, 3, 0}));

  const Eigen::Vector4d point(0.5, -0.5, 2.0, 4.0);
  Eigen::Vector3d g;
  VectorXd values(4);
  assembly.EvalConstraintsAndJacobian(point.data(), g.data(), values.data());
  EXPECT_EQ(g, Eigen::Vector3d(2.0, 12.0, 2.0));
  EXPECT_EQ(values, Eigen::Vector4d(1.0, 3.0, 0.5, 4.0));
  // Row 0 (x2 <= 1) is violated by 1; row 1 by 10; the product row by 1.
  EXPECT_DOUBLE_EQ(assembly.ConstraintViolation(point.data()), 10.0);
  EXPECT_EQ(assembly.DescribeWorstViolation(point.data()),
            "constraint 'LinearConstraint(x[2:4])' row 1 (value 12, bounds [-inf, 2])");
}

// The assembled Lagrangian Hessian must equal the derivative of the assembled Lagrangian gradient, including
// the J'J + sum r_k Hessian(r_k) term of least-squares costs and the merging of entries shared by several terms.
TEST(ProgramAssemblyTest, LagrangianHessianMatchesDifferencesOfTheGradient) {
  test::TestProblem hs071 = test::MakeHs071();
  MathematicalProgram& prog = *hs071.prog;
  test::TestProblem chain = test::MakeChainedRosenbrock(4);  // not used directly; its link has a residual Hessian
  auto link = chain.prog->least_squares_costs().front().evaluator();
  prog.AddLeastSquaresCost(link, hs071.x.Segment(1, 2));
  prog.AddLeastSquaresCost(link, DecisionVariables::Concatenate({hs071.x.Element(3), hs071.x.Element(0)}));
  ProgramAssembly assembly(prog);
  ASSERT_TRUE(assembly.has_hessian());
  const int n = assembly.num_vars();
  const int m = assembly.num_constraints();
  const Eigen::Vector4d x(1.1, 2.3, 3.2, 1.7);
  const Eigen::Vector2d lambda(0.7, -1.9);
  const double sigma = 1.3;
  // grad L = sigma * grad f + J' lambda
  auto lagrangian_gradient = [&](const Eigen::Vector4d& at) {
    VectorXd grad(n), g(m), values(assembly.jacobian_nonzeros());
    assembly.EvalCostAndGradient(at.data(), grad.data());
    grad *= sigma;
    assembly.EvalConstraintsAndJacobian(at.data(), g.data(), values.data());
    for (int k = 0; k < values.size(); ++k) {
      grad[assembly.jacobian_cols()[k]] += lambda[assembly.jacobian_rows()[k]] * values[k];
    }
    return grad;
  };
  VectorXd h(static_cast<Eigen::Index>(assembly.hessian_rows().size()));
  assembly.EvalLagrangianHessian(x.data(), sigma, lambda.data(), h.data());
  Eigen::MatrixXd H = Eigen::MatrixXd::Zero(n, n);
  std::set<std::pair<int, int>> entries;
  for (int k = 0; k < h.size(); ++k) {
    EXPECT_GE(assembly.hessian_rows()[k], assembly.hessian_cols()[k]);
    EXPECT_TRUE(entries.insert({assembly.hessian_rows()[k], assembly.hessian_cols()[k]}).second) << "duplicate";
    H(assembly.hessian_rows()[k], assembly.hessian_cols()[k]) = h[k];
  }
  for (int j = 0; j < n; ++j) {
    Eigen::Vector4d plus = x, minus = x;
    plus[j] += 1e-6;
    minus[j] -= 1e-6;
    const VectorXd column = (lagrangian_gradient(plus) - lagrangian_gradient(minus)) / 2e-6;
    for (int i = j; i < n; ++i) EXPECT_NEAR(H(i, j), column[i], 1e-5 * (1 + std::abs(column[i]))) << i << "," << j;
  }
}

// Gauss-Newton keeps J'J of every least-squares cost and drops the residuals' curvature, so a residual without
// a Hessian no longer blocks the exact-Hessian path, and the result is the J'J of the stacked residual Jacobian.
TEST(ProgramAssemblyTest, GaussNewtonHessianIsJTransposeJ) {
  MathematicalProgram prog;
  const auto x = prog.NewContinuousVariables(3, "x");
  // r(a, b) = (a b, a^2 - b): curved, and declares no Hessian.
  auto residual = std::make_shared<FunctionEvaluator>(
      "curved", 2, 2, std::vector<SparsityEntry>{{0, 0}, {0, 1}, {1, 0}, {1, 1}},
      [](const Ref<const VectorXd>& v, Ref<VectorXd> r) { r << v[0] * v[1], v[0] * v[0] - v[1]; },
      [](const Ref<const VectorXd>& v, Ref<VectorXd> r, Ref<VectorXd> j) {
        r << v[0] * v[1], v[0] * v[0] - v[1];
        j << v[1], v[0], 2 * v[0], -1;
      });
  prog.AddLeastSquaresCost(residual, x.Segment(0, 2));
  prog.AddLeastSquaresCost(residual, DecisionVariables::Concatenate({x.Element(2), x.Element(0)}));
  EXPECT_FALSE(ProgramAssembly(prog).has_hessian());
  ProgramAssembly assembly(prog, ProgramAssembly::LeastSquaresHessian::kGaussNewton);
  ASSERT_TRUE(assembly.has_hessian());
  const Eigen::Vector3d at(0.3, -1.2, 2.1);
  VectorXd r(assembly.num_residuals());
  VectorXd jac(static_cast<Eigen::Index>(assembly.residual_jacobian_rows().size()));
  assembly.EvalResidualsAndJacobian(at.data(), r.data(), jac.data());
  Eigen::MatrixXd J = Eigen::MatrixXd::Zero(assembly.num_residuals(), 3);
  for (int k = 0; k < jac.size(); ++k) J(assembly.residual_jacobian_rows()[k], assembly.residual_jacobian_cols()[k]) += jac[k];
  const Eigen::MatrixXd expected = 2.5 * J.transpose() * J;  // objective factor 2.5
  VectorXd h(static_cast<Eigen::Index>(assembly.hessian_rows().size()));
  assembly.EvalLagrangianHessian(at.data(), 2.5, nullptr, h.data());
  Eigen::MatrixXd H = Eigen::MatrixXd::Zero(3, 3);
  for (int k = 0; k < h.size(); ++k) H(assembly.hessian_rows()[k], assembly.hessian_cols()[k]) = h[k];
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j <= i; ++j) EXPECT_NEAR(H(i, j), expected(i, j), 1e-12) << i << "," << j;
  }
}

TEST(ProgramAssemblyTest, NoHessianWhenATermLacksOne) {
  const test::TestProblem hs100 = test::MakeHs100();
  EXPECT_FALSE(ProgramAssembly(*hs100.prog).has_hessian());
  const test::TestProblem hs035 = test::MakeHs035();
  EXPECT_TRUE(ProgramAssembly(*hs035.prog).has_hessian());
}

}  // namespace
}  // namespace cairn::optimization
