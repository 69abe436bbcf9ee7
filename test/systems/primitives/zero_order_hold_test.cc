#include "cairn/systems/primitives/zero_order_hold.h"

#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "cairn/systems/analysis/simulator.h"
#include "cairn/systems/framework/diagram_builder.h"
#include "cairn/systems/primitives/function_system.h"
#include "expect_throws.h"

namespace cairn::systems {
namespace {

TEST(ZeroOrderHoldTest, HoldsTheLastSampleBetweenPeriods) {
  DiagramBuilder builder;
  auto* clock = builder.AddSystem<FunctionSystem>(0, 1, [](double t, const Eigen::VectorXd&) {
    return Eigen::VectorXd::Constant(1, t);
  });
  auto* hold = builder.AddNamedSystem<ZeroOrderHold>("hold", 0.25, 1);
  builder.Connect(*clock, *hold);
  builder.ExportOutput(hold->get_output_port(), "y");
  auto diagram = builder.Build();
  EXPECT_FALSE(hold->HasDirectFeedthrough(0, 0));
  Simulator simulator(*diagram);
  simulator.AdvanceTo(0.6);
  // Samples at 0, 0.25, 0.5: the output holds 0.5.
  EXPECT_EQ(diagram->get_output_port().Eval<Eigen::VectorXd>(simulator.get_context())[0], 0.5);
}

TEST(ZeroOrderHoldTest, HoldsAbstractValues) {
  ZeroOrderHold hold(0.1, Value<std::string>("initial"));
  auto context = hold.CreateDefaultContext();
  hold.get_input_port().FixValue(context.get(), std::string("sampled"));
  EXPECT_EQ(hold.get_output_port().Eval<std::string>(*context), "initial");
  Simulator simulator(hold, std::move(context));
  simulator.AdvanceTo(0.05);
  EXPECT_EQ(hold.get_output_port().Eval<std::string>(simulator.get_context()), "sampled");
}

TEST(ZeroOrderHoldTest, PeriodsMustBeFiniteAndPositive) {
  CAIRN_EXPECT_THROWS_WITH(ZeroOrderHold(std::nan(""), 1), std::invalid_argument,
                           "ZeroOrderHold: the sampling period must be finite and > 0; got nan");
  CAIRN_EXPECT_THROWS_WITH(ZeroOrderHold(HUGE_VAL, 1), std::invalid_argument, "got inf");
  CAIRN_EXPECT_THROWS_WITH(ZeroOrderHold(0.0, Value<std::string>("x")), std::invalid_argument, "got 0");
}

}  // namespace
}  // namespace cairn::systems
