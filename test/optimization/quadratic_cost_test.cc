#include "cairn/optimization/quadratic_cost.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "expect_throws.h"

namespace cairn::optimization {
namespace {

using ::testing::HasSubstr;

TEST(QuadraticCostTest, ValueGradientAndHessianLowerTriangle) {
  Eigen::Matrix2d Q;
  Q << 2, 1, 1, 4;
  const QuadraticCost cost(Q.sparseView(), Eigen::Vector2d(-1, 3), 0.5);
  const Eigen::Vector2d x(1.5, -2);
  EXPECT_DOUBLE_EQ(cost.Eval(x)[0], 0.5 * x.dot(Q * x) + Eigen::Vector2d(-1, 3).dot(x) + 0.5);
  EXPECT_TRUE(Eigen::MatrixXd(cost.EvalJacobian(x)).isApprox((Q * x + Eigen::Vector2d(-1, 3)).transpose()));
  ASSERT_EQ(cost.hessian_pattern().size(), 3u);  // (0,0), (1,0), (1,1)
  Eigen::VectorXd h(3);
  cost.EvalHessian(x, Eigen::Matrix<double, 1, 1>(2.0), h);
  EXPECT_EQ(h, Eigen::Vector3d(4, 2, 8));
}

TEST(QuadraticCostTest, RejectsBadShapes) {
  CAIRN_EXPECT_THROWS_WITH(QuadraticCost(Eigen::Matrix2d::Identity().sparseView(), Eigen::Vector3d::Zero(), 0.0),
                           std::invalid_argument,
                           "QuadraticCost: Q is 2 x 2 and b has size 3; Q must be square with as many rows as b");
  Eigen::Matrix2d asymmetric;
  asymmetric << 1, 2, 0, 1;
  CAIRN_EXPECT_THROWS_WITH(QuadraticCost(asymmetric.sparseView(), Eigen::Vector2d::Zero(), 0.0), std::invalid_argument,
                           "pass (Q + Q')/2 for the same cost");
}

}  // namespace
}  // namespace cairn::optimization
