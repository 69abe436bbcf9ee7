#include "cairn/systems/primitives/adder.h"

#include <gtest/gtest.h>

#include "expect_throws.h"

namespace cairn::systems {
namespace {

TEST(AdderTest, SumsAllInputs) {
  Adder adder(3, 2);
  auto context = adder.CreateDefaultContext();
  adder.get_input_port(0).FixValue(context.get(), Eigen::Vector2d(1.0, 2.0));
  adder.get_input_port(1).FixValue(context.get(), Eigen::Vector2d(10.0, 20.0));
  adder.get_input_port(2).FixValue(context.get(), Eigen::Vector2d(100.0, 200.0));
  EXPECT_EQ(adder.get_output_port().Eval<Eigen::VectorXd>(*context), Eigen::Vector2d(111.0, 222.0));
  EXPECT_TRUE(adder.HasDirectFeedthrough(2, 0));
  CAIRN_EXPECT_THROWS_WITH(Adder(0, 2), std::invalid_argument, "at least one input", "num_inputs = 0");
}

}  // namespace
}  // namespace cairn::systems
