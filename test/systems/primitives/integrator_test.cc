#include "cairn/systems/primitives/integrator.h"

#include <cmath>

#include <gtest/gtest.h>

#include "expect_throws.h"

namespace cairn::systems {
namespace {

TEST(IntegratorPrimitiveTest, DerivativeIsTheInputAndOutputIsTheState) {
  Integrator integrator(Eigen::Vector2d(1.0, 2.0));
  EXPECT_FALSE(integrator.HasDirectFeedthrough(0, 0));
  auto context = integrator.CreateDefaultContext();
  integrator.get_input_port().FixValue(context.get(), Eigen::Vector2d(3.0, -3.0));
  Eigen::VectorXd derivatives;
  integrator.CalcTimeDerivatives(*context, &derivatives);
  EXPECT_EQ(derivatives, Eigen::Vector2d(3.0, -3.0));
  EXPECT_EQ(integrator.get_output_port().Eval<Eigen::VectorXd>(*context), Eigen::Vector2d(1.0, 2.0));
}

TEST(IntegratorPrimitiveTest, NonFiniteInitialValuesAreRefused) {
  CAIRN_EXPECT_THROWS_WITH(Integrator(Eigen::Vector2d(0.0, std::nan(""))), std::invalid_argument,
                           "Integrator: initial value element 1 is nan", "finite");
}

}  // namespace
}  // namespace cairn::systems
