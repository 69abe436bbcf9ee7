#include "cairn/optimization/constraint.h"

#include <limits>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "cairn/optimization/bounding_box_constraint.h"
#include "cairn/optimization/evaluator_constraint.h"
#include "cairn/optimization/function_evaluator.h"
#include "cairn/optimization/linear_constraint.h"
#include "cairn/optimization/linear_equality_constraint.h"
#include "expect_throws.h"

namespace cairn::optimization {
namespace {

using Eigen::Ref;
using Eigen::VectorXd;
using ::testing::HasSubstr;
constexpr double kInf = std::numeric_limits<double>::infinity();

TEST(ConstraintTest, LinearKindsEvaluateAndReportViolation) {
  Eigen::SparseMatrix<double> A(2, 3);
  A.insert(0, 0) = 1.0;
  A.insert(0, 2) = -1.0;
  A.insert(1, 1) = 2.0;
  const LinearConstraint linear(A, Eigen::Vector2d(-kInf, 0.0), Eigen::Vector2d(1.0, 0.0));
  EXPECT_EQ(linear.jacobian_nonzeros(), 3);
  EXPECT_EQ(linear.Eval(Eigen::Vector3d(3, 1, 1)), Eigen::Vector2d(2, 2));
  EXPECT_DOUBLE_EQ(linear.Violation(Eigen::Vector3d(3, 1, 1)), 2.0);
  EXPECT_TRUE(Eigen::MatrixXd(linear.EvalJacobian(Eigen::Vector3d::Zero())).isApprox(Eigen::MatrixXd(A)));

  const LinearEqualityConstraint equality(A, Eigen::Vector2d(1, 2));
  EXPECT_EQ(equality.b(), Eigen::Vector2d(1, 2));
  EXPECT_EQ(equality.upper_bound(), Eigen::Vector2d(1, 2));
  EXPECT_EQ(equality.name(), "LinearEqualityConstraint");

  const BoundingBoxConstraint box(Eigen::Vector2d(0, -1), Eigen::Vector2d(1, 1));
  EXPECT_DOUBLE_EQ(box.Violation(Eigen::Vector2d(1.5, 0)), 0.5);
}

TEST(ConstraintTest, EvaluatorConstraintForwardsEverything) {
  auto f = std::make_shared<FunctionEvaluator>(
      "square", 1, 1, Evaluator::DensePattern(1, 1),
      [](const Ref<const VectorXd>& v, Ref<VectorXd> y) { y[0] = v[0] * v[0]; },
      [](const Ref<const VectorXd>& v, Ref<VectorXd> y, Ref<VectorXd> j) {
        y[0] = v[0] * v[0];
        j[0] = 2 * v[0];
      },
      std::vector<SparsityEntry>{{0, 0}},
      [](const Ref<const VectorXd>&, const Ref<const VectorXd>& w, Ref<VectorXd> h) { h[0] = 2 * w[0]; });
  const EvaluatorConstraint c(f, Eigen::Matrix<double, 1, 1>(-kInf), Eigen::Matrix<double, 1, 1>(4.0));
  EXPECT_EQ(c.name(), "square");
  EXPECT_TRUE(c.has_hessian());
  EXPECT_EQ(c.jacobian_source(), DerivativeSource::kAnalytic);
  EXPECT_DOUBLE_EQ(c.Violation(Eigen::Matrix<double, 1, 1>(3.0)), 5.0);
  Eigen::VectorXd h(1);
  c.EvalHessian(Eigen::Matrix<double, 1, 1>(3.0), Eigen::Matrix<double, 1, 1>(1.5), h);
  EXPECT_DOUBLE_EQ(h[0], 3.0);
}

TEST(ConstraintTest, RejectsBadBoundsAndInputs) {
  Eigen::SparseMatrix<double> A(1, 2);
  A.insert(0, 0) = 1.0;
  CAIRN_EXPECT_THROWS_WITH(LinearConstraint(A, Eigen::Vector2d(0, 0), Eigen::Vector2d(1, 1)), std::invalid_argument,
                           "Constraint 'LinearConstraint': lower bound has size 2 and upper bound 2; both need one "
                           "entry per output (1)");
  CAIRN_EXPECT_THROWS_WITH(
      ([&] { LinearConstraint(A, Eigen::Matrix<double, 1, 1>(std::nan("")), Eigen::Matrix<double, 1, 1>(1)); })(),
      std::invalid_argument, "bounds must not be NaN and need lower <= upper");
  A.coeffRef(0, 1) = kInf;
  CAIRN_EXPECT_THROWS_WITH(
      ([&] { LinearConstraint(A, Eigen::Matrix<double, 1, 1>(0), Eigen::Matrix<double, 1, 1>(1)); })(),
      std::invalid_argument, "the matrix A has a non-finite entry");
  A.coeffRef(0, 1) = 1.0;
  CAIRN_EXPECT_THROWS_WITH((LinearEqualityConstraint(A, Eigen::Matrix<double, 1, 1>(kInf))), std::invalid_argument,
                           "LinearEqualityConstraint: the right-hand side b has a non-finite entry");
  CAIRN_EXPECT_THROWS_WITH(
      ([] { EvaluatorConstraint(nullptr, Eigen::Matrix<double, 1, 1>(0), Eigen::Matrix<double, 1, 1>(1)); })(),
      std::invalid_argument, "EvaluatorConstraint: the evaluator is null");
}

}  // namespace
}  // namespace cairn::optimization
