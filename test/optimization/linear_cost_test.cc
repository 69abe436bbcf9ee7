#include "cairn/optimization/linear_cost.h"

#include <limits>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "expect_throws.h"

namespace cairn::optimization {
namespace {

using ::testing::HasSubstr;

TEST(LinearCostTest, ValueGradientAndEmptyHessian) {
  const LinearCost cost(Eigen::Vector3d(1, -2, 0.5), 4.0);
  EXPECT_DOUBLE_EQ(cost.Eval(Eigen::Vector3d(1, 1, 2))[0], 4.0);
  EXPECT_EQ(Eigen::MatrixXd(cost.EvalJacobian(Eigen::Vector3d::Zero())), Eigen::RowVector3d(1, -2, 0.5));
  EXPECT_TRUE(cost.has_hessian());
  EXPECT_TRUE(cost.hessian_pattern().empty());
}

TEST(LinearCostTest, RejectsNonFiniteCoefficients) {
  CAIRN_EXPECT_THROWS_WITH((LinearCost(Eigen::Vector2d(1, std::numeric_limits<double>::quiet_NaN()), 0.0)),
                           std::invalid_argument, "LinearCost: the coefficients a and the constant b must be finite");
}

}  // namespace
}  // namespace cairn::optimization
