#include "cairn/systems/primitives/function_system.h"

#include <cmath>

#include <gtest/gtest.h>

#include "expect_throws.h"

namespace cairn::systems {
namespace {

TEST(FunctionSystemTest, WrapsAFunctionOfTimeAndInput) {
  FunctionSystem system(2, 1, [](double t, const Eigen::VectorXd& u) {
    return Eigen::VectorXd::Constant(1, t * u.sum());
  });
  auto context = system.CreateDefaultContext();
  context->SetTime(2.0);
  system.get_input_port().FixValue(context.get(), Eigen::Vector2d(1.0, 3.0));
  EXPECT_EQ(system.get_output_port().Eval<Eigen::VectorXd>(*context)[0], 8.0);

  FunctionSystem source(0, 1, [](double t, const Eigen::VectorXd&) { return Eigen::VectorXd::Constant(1, std::sin(t)); });
  EXPECT_EQ(source.num_input_ports(), 0);
  auto source_context = source.CreateDefaultContext();
  source_context->SetTime(0.5);
  EXPECT_EQ(source.get_output_port().Eval<Eigen::VectorXd>(*source_context)[0], std::sin(0.5));
}

TEST(FunctionSystemTest, WrongOutputSizeIsReported) {
  FunctionSystem system(0, 2, [](double, const Eigen::VectorXd&) { return Eigen::VectorXd::Zero(3); });
  system.set_name("f");
  auto context = system.CreateDefaultContext();
  CAIRN_EXPECT_THROWS_WITH(system.get_output_port().Eval<Eigen::VectorXd>(*context), std::logic_error,
                           "FunctionSystem 'f' returned a vector of size 3", "has size 2");
  CAIRN_EXPECT_THROWS_WITH(FunctionSystem(0, 1, nullptr), std::invalid_argument, "function is empty");
}

}  // namespace
}  // namespace cairn::systems
