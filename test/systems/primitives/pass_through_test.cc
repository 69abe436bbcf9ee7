#include "cairn/systems/primitives/pass_through.h"

#include <string>

#include <gtest/gtest.h>

namespace cairn::systems {
namespace {

TEST(PassThroughTest, CopiesVectorsAndAbstractValues) {
  PassThrough vector(2);
  auto context = vector.CreateDefaultContext();
  vector.get_input_port().FixValue(context.get(), Eigen::Vector2d(5.0, 6.0));
  EXPECT_EQ(vector.get_output_port().Eval<Eigen::VectorXd>(*context), Eigen::Vector2d(5.0, 6.0));

  PassThrough text(Value<std::string>("model"));
  auto text_context = text.CreateDefaultContext();
  text.get_input_port().FixValue(text_context.get(), std::string("copied"));
  EXPECT_EQ(text.get_output_port().Eval<std::string>(*text_context), "copied");
  EXPECT_TRUE(text.HasDirectFeedthrough(0, 0));
}

}  // namespace
}  // namespace cairn::systems
