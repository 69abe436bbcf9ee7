#include "cairn/systems/primitives/gain.h"

#include <cmath>

#include <gtest/gtest.h>

#include "expect_throws.h"

namespace cairn::systems {
namespace {

TEST(GainTest, ScalarAndPerElementGains) {
  Gain scalar(2.0, 3);
  auto context = scalar.CreateDefaultContext();
  scalar.get_input_port().FixValue(context.get(), Eigen::Vector3d(1.0, 2.0, 3.0));
  EXPECT_EQ(scalar.get_output_port().Eval<Eigen::VectorXd>(*context), Eigen::Vector3d(2.0, 4.0, 6.0));

  Gain per_element(Eigen::Vector2d(-1.0, 0.5));
  auto other = per_element.CreateDefaultContext();
  per_element.get_input_port().FixValue(other.get(), Eigen::Vector2d(4.0, 4.0));
  EXPECT_EQ(per_element.get_output_port().Eval<Eigen::VectorXd>(*other), Eigen::Vector2d(-4.0, 2.0));
  EXPECT_TRUE(per_element.HasDirectFeedthrough(0, 0));
  CAIRN_EXPECT_THROWS_WITH(Gain(1.0, 0), std::invalid_argument, "size must be positive");
}

TEST(GainTest, NonFiniteAndEmptyGainsAreRefused) {
  CAIRN_EXPECT_THROWS_WITH(Gain(std::nan(""), 2), std::invalid_argument, "gain element 0 is nan", "finite");
  CAIRN_EXPECT_THROWS_WITH(Gain(Eigen::Vector2d(1.0, -HUGE_VAL)), std::invalid_argument, "gain element 1 is -inf");
  CAIRN_EXPECT_THROWS_WITH(Gain(Eigen::VectorXd()), std::invalid_argument, "must not be empty");
  CAIRN_EXPECT_THROWS_WITH(Gain(1.0, -3), std::invalid_argument, "size must be positive; got -3");
}

}  // namespace
}  // namespace cairn::systems
