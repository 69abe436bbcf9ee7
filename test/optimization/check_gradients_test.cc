#include "cairn/optimization/check_gradients.h"

#include <cmath>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "cairn/optimization/function_evaluator.h"
#include "test_problems.h"
#include "expect_throws.h"

namespace cairn::optimization {
namespace {

using Eigen::Ref;
using Eigen::VectorXd;
using ::testing::HasSubstr;

TEST(CheckGradientsTest, CorrectDerivativesPass) {
  for (const test::TestProblem& p : {test::MakeHs071(), test::MakeHs100(), test::MakeHs035(),
                                     test::MakeChainedRosenbrock(6)}) {
    const GradientCheckResult result = CheckGradients(*p.prog, p.prog->initial_guess() + VectorXd::Constant(
                                                                                          p.prog->num_vars(), 0.1));
    EXPECT_TRUE(result.passed) << p.name << "\n" << result.ToString();
    EXPECT_GT(result.num_checked, 0);
  }
}

TEST(CheckGradientsTest, CatchesADeliberatelyWrongJacobianAndNamesIt) {
  test::TestProblem p = test::MakeHs071();
  // d/dx1 of x0 * x1^2 is 2 x0 x1; this evaluator reports x0 x1.
  auto wrong = std::make_shared<FunctionEvaluator>(
      "wrong_derivative", 2, 1, Evaluator::DensePattern(1, 2),
      [](const Ref<const VectorXd>& v, Ref<VectorXd> y) { y[0] = v[0] * v[1] * v[1]; },
      [](const Ref<const VectorXd>& v, Ref<VectorXd> y, Ref<VectorXd> j) {
        y[0] = v[0] * v[1] * v[1];
        j << v[1] * v[1], v[0] * v[1];
      });
  p.prog->AddConstraint(wrong, Eigen::Matrix<double, 1, 1>(0.0), Eigen::Matrix<double, 1, 1>(10.0),
                        p.x.Segment(2, 2));
  const GradientCheckResult result = CheckGradients(*p.prog, Eigen::Vector4d(1.5, 2.0, 3.0, 2.5));
  EXPECT_FALSE(result.passed);
  EXPECT_EQ(result.num_failed, 1);
  ASSERT_FALSE(result.worst_entries.empty());
  const GradientCheckResult::Entry& worst = result.worst_entries.front();
  EXPECT_EQ(worst.term, "wrong_derivative(x[2:4])");
  EXPECT_EQ(worst.variable, "x(3)");
  EXPECT_NEAR(worst.analytic, 3.0 * 2.5, 1e-12);
  EXPECT_NEAR(worst.finite_difference, 2 * 3.0 * 2.5, 1e-6);
  EXPECT_THAT(result.ToString(),
              HasSubstr("constraint 'wrong_derivative(x[2:4])' d(output 0)/d(x(3)): evaluator 7.5 [analytic], "
                        "finite difference 15"));
}

TEST(CheckGradientsTest, CatchesAnEntryMissingFromTheDeclaredPattern) {
  MathematicalProgram prog;
  const auto x = prog.NewContinuousVariables(2, "x");
  // The value depends on x1, but the pattern declares only (0, 0).
  prog.AddCost(std::make_shared<FunctionEvaluator>(
                   "forgot_x1", 2, 1, std::vector<SparsityEntry>{{0, 0}},
                   [](const Ref<const VectorXd>& v, Ref<VectorXd> y) { y[0] = v[0] + 4 * v[1]; },
                   [](const Ref<const VectorXd>& v, Ref<VectorXd> y, Ref<VectorXd> j) {
                     y[0] = v[0] + 4 * v[1];
                     j[0] = 1.0;
                   }),
               x);
  const GradientCheckResult result = CheckGradients(prog, Eigen::Vector2d(0.3, 0.4));
  EXPECT_FALSE(result.passed);
  ASSERT_FALSE(result.worst_entries.empty());
  EXPECT_FALSE(result.worst_entries.front().in_pattern);
  EXPECT_THAT(result.ToString(), HasSubstr("cost 'forgot_x1(x)' d(output 0)/d(x(1)): missing from the declared "
                                           "pattern"));
}

TEST(CheckGradientsTest, CatchesAWrongHessian) {
  MathematicalProgram prog;
  const auto x = prog.NewContinuousVariables(1, "x");
  prog.AddCost(std::make_shared<FunctionEvaluator>(
                   "cube", 1, 1, Evaluator::DensePattern(1, 1),
                   [](const Ref<const VectorXd>& v, Ref<VectorXd> y) { y[0] = v[0] * v[0] * v[0]; },
                   [](const Ref<const VectorXd>& v, Ref<VectorXd> y, Ref<VectorXd> j) {
                     y[0] = v[0] * v[0] * v[0];
                     j[0] = 3 * v[0] * v[0];
                   },
                   std::vector<SparsityEntry>{{0, 0}},
                   [](const Ref<const VectorXd>& v, const Ref<const VectorXd>& w, Ref<VectorXd> h) {
                     h[0] = w[0] * 3 * v[0];  // should be 6 x
                   }),
               x);
  const GradientCheckResult result = CheckGradients(prog, Eigen::Matrix<double, 1, 1>(2.0));
  EXPECT_FALSE(result.passed);
  EXPECT_THAT(result.ToString(), HasSubstr("cost Hessian 'cube(x)' d2/d(x)d(x): evaluator 6"));
}

TEST(CheckGradientsTest, ChecksASingleEvaluator) {
  const FunctionEvaluator wrong(
      "sine", 1, 1, Evaluator::DensePattern(1, 1),
      [](const Ref<const VectorXd>& v, Ref<VectorXd> y) { y[0] = std::sin(v[0]); },
      [](const Ref<const VectorXd>& v, Ref<VectorXd> y, Ref<VectorXd> j) {
        y[0] = std::sin(v[0]);
        j[0] = -std::cos(v[0]);  // sign error
      });
  const GradientCheckResult result = CheckGradients(wrong, Eigen::Matrix<double, 1, 1>(0.3));
  EXPECT_FALSE(result.passed);
  EXPECT_THAT(result.ToString(), HasSubstr("evaluator 'sine(x)' d(output 0)/d(x)"));
  CAIRN_EXPECT_THROWS_WITH(CheckGradients(wrong, Eigen::Vector2d(1, 2)), std::invalid_argument,
                           "x has size 2 but evaluator 'sine' takes 1 inputs");
}

TEST(CheckGradientsTest, RejectsBadArguments) {
  const test::TestProblem p = test::MakeHs071();
  CAIRN_EXPECT_THROWS_WITH(CheckGradients(*p.prog, Eigen::Vector2d(1, 1)), std::invalid_argument,
                           "CheckGradients: x has size 2 but the program has 4 variables");
  CAIRN_EXPECT_THROWS_WITH(CheckGradients(*p.prog, Eigen::Vector4d::Ones(), 0.0), std::invalid_argument,
                           "tolerance = 0.000000 must be positive");
}

}  // namespace
}  // namespace cairn::optimization
