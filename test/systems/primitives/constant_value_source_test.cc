#include "cairn/systems/primitives/constant_value_source.h"

#include <string>

#include <gtest/gtest.h>

namespace cairn::systems {
namespace {

TEST(ConstantValueSourceTest, OutputsItsValuePerContext) {
  ConstantValueSource<std::string> source("hello");
  auto context = source.CreateDefaultContext();
  EXPECT_EQ(source.get_output_port().Eval<std::string>(*context), "hello");
  context->get_mutable_abstract_parameter<std::string>(0) = "changed";
  EXPECT_EQ(source.get_output_port().Eval<std::string>(*context), "changed");
  EXPECT_EQ(source.get_output_port().Eval<std::string>(*source.CreateDefaultContext()), "hello");
}

}  // namespace
}  // namespace cairn::systems
