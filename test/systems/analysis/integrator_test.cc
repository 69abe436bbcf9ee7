#include <cmath>
#include <memory>

#include <gtest/gtest.h>

#include "cairn/systems/analysis/explicit_euler_integrator.h"
#include "cairn/systems/analysis/runge_kutta45_integrator.h"
#include "cairn/systems/analysis/runge_kutta4_integrator.h"
#include "cairn/systems/analysis/simulator.h"
#include "cairn/systems/framework/leaf_system.h"
#include "expect_throws.h"

namespace cairn::systems {
namespace {

// x' = A x for a lightly damped oscillator; the exact solution is known in closed form.
class Oscillator final : public LeafSystem {
 public:
  Oscillator() { DeclareContinuousState(Eigen::Vector2d(1.0, 0.0)); }
  static constexpr double kOmega = 2.0;
  static constexpr double kZeta = 0.1;

  // Exact solution from x(0) = 1, x'(0) = 0.
  static double Exact(double t) {
    const double wd = kOmega * std::sqrt(1.0 - kZeta * kZeta);
    return std::exp(-kZeta * kOmega * t) * (std::cos(wd * t) + kZeta * kOmega / wd * std::sin(wd * t));
  }

 private:
  void DoCalcTimeDerivatives(const Context& context, Eigen::Ref<Eigen::VectorXd> derivatives) const override {
    const auto x = context.get_continuous_state_vector();
    derivatives[0] = x[1];
    derivatives[1] = -kOmega * kOmega * x[0] - 2.0 * kZeta * kOmega * x[1];
  }
};

template <class I>
double ErrorAtOneSecond(double h) {
  Oscillator system;
  Simulator simulator(system);
  simulator.ResetIntegrator<I>(h);
  simulator.AdvanceTo(1.0);
  return std::abs(simulator.get_context().get_continuous_state_vector()[0] - Oscillator::Exact(1.0));
}

TEST(IntegratorTest, ExplicitEulerConvergesAtFirstOrder) {
  const double coarse = ErrorAtOneSecond<ExplicitEulerIntegrator>(1.0 / 200);
  const double fine = ErrorAtOneSecond<ExplicitEulerIntegrator>(1.0 / 400);
  EXPECT_NEAR(coarse / fine, 2.0, 0.1);
}

TEST(IntegratorTest, RungeKutta4ConvergesAtFourthOrder) {
  const double coarse = ErrorAtOneSecond<RungeKutta4Integrator>(1.0 / 20);
  const double fine = ErrorAtOneSecond<RungeKutta4Integrator>(1.0 / 40);
  EXPECT_NEAR(coarse / fine, 16.0, 1.0);
}

TEST(IntegratorTest, RungeKutta45MeetsItsAccuracyWithFewerSteps) {
  Oscillator system;
  Simulator simulator(system);
  auto& rk45 = simulator.ResetIntegrator<RungeKutta45Integrator>(0.5, 1e-9);
  simulator.AdvanceTo(5.0);
  const double error = std::abs(simulator.get_context().get_continuous_state_vector()[0] - Oscillator::Exact(5.0));
  EXPECT_LT(error, 1e-7);
  EXPECT_LT(rk45.num_steps_taken(), 500);  // RK4 at 1 ms takes 5000 steps for the same span.
  // And it agrees with RK4 at a small step.
  Simulator reference(system);
  reference.ResetIntegrator<RungeKutta4Integrator>(1e-3);
  reference.AdvanceTo(5.0);
  EXPECT_NEAR(simulator.get_context().get_continuous_state_vector()[0],
              reference.get_context().get_continuous_state_vector()[0], 1e-7);
}

TEST(IntegratorTest, StepsNeverOvershootTheTarget) {
  Oscillator system;
  auto context = system.CreateDefaultContext();
  RungeKutta4Integrator rk4(0.3);
  EXPECT_DOUBLE_EQ(rk4.Step(system, context.get(), 1.0), 0.3);
  context->SetTime(0.9);
  EXPECT_EQ(rk4.Step(system, context.get(), 1.0), 1.0);
  // Within 1% over the remainder, the step stretches to land on the target.
  context->SetTime(0.0);
  EXPECT_EQ(rk4.Step(system, context.get(), 0.302), 0.302);
  CAIRN_EXPECT_THROWS_WITH(rk4.Step(system, context.get(), 0.1), std::invalid_argument, "not after the current time");
  CAIRN_EXPECT_THROWS_WITH(rk4.set_maximum_step_size(0.0), std::invalid_argument, "finite and > 0");
  CAIRN_EXPECT_THROWS_WITH(RungeKutta45Integrator(0.1, 2.0), std::invalid_argument, "accuracy must be in (0, 1)");
}

}  // namespace
}  // namespace cairn::systems
