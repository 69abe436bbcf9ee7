#include <cmath>
#include <limits>
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

// x' = 1e300 x: one explicit step of any useful size overflows.
class Exploding final : public LeafSystem {
 public:
  Exploding() { DeclareContinuousState(Eigen::VectorXd::Ones(1)); }

 private:
  void DoCalcTimeDerivatives(const Context& context, Eigen::Ref<Eigen::VectorXd> derivatives) const override {
    derivatives = 1e300 * context.get_continuous_state_vector();
  }
};

TEST(IntegratorTest, AStepThatCannotAdvanceTimeIsRefused) {
  Oscillator system;
  auto context = system.CreateDefaultContext();
  context->SetTime(1.0);
  // 1 + 1e-20 == 1: the step would be repeated forever.
  RungeKutta4Integrator rk4(1e-20);
  CAIRN_EXPECT_THROWS_WITH(rk4.Step(system, context.get(), 2.0), std::invalid_argument, "'rk4'",
                           "maximum step size 1e-20 s cannot advance time from t = 1", "2.22045e-16 s apart");
  ExplicitEulerIntegrator euler(1e-17);
  CAIRN_EXPECT_THROWS_WITH(euler.Step(system, context.get(), 2.0), std::invalid_argument, "'explicit_euler'",
                           "1e-17 s");
  // Near t = 0 the same step does advance (the Simulator's step limit is what bounds such a run).
  context->SetTime(0.0);
  EXPECT_EQ(rk4.Step(system, context.get(), 2.0), 1e-20);
  CAIRN_EXPECT_THROWS_WITH(rk4.Step(system, context.get(), std::numeric_limits<double>::infinity()),
                           std::invalid_argument, "t_max = inf", "not finite");
}

TEST(IntegratorTest, RungeKutta45RaisesATrialStepThatCannotAdvanceTime) {
  Oscillator system;
  auto context = system.CreateDefaultContext();
  context->SetTime(1e6);
  // The first trial step, a hundredth of the maximum, is below the spacing of doubles at 1e6 (1.2e-10).
  RungeKutta45Integrator rk45(1e-9, 1e-6);
  const double reached = rk45.Step(system, context.get(), 1e6 + 1.0);
  EXPECT_GT(reached, 1e6);
  EXPECT_LE(reached - 1e6, 1.1e-9);
  CAIRN_EXPECT_THROWS_WITH(rk45.set_minimum_step_size(std::numeric_limits<double>::quiet_NaN()),
                           std::invalid_argument, "minimum step size must be finite and > 0; got nan");
}

TEST(IntegratorTest, ADivergedStateIsReportedWithTheStep) {
  Exploding system;
  auto context = system.CreateDefaultContext();
  ExplicitEulerIntegrator euler(0.5);
  euler.Step(system, context.get(), 10.0);  // x = 5e299
  CAIRN_EXPECT_THROWS_WITH(euler.Step(system, context.get(), 10.0), std::runtime_error, "'explicit_euler'",
                           "became non-finite (element 0 = inf)", "from t = 0.5 to 1", "diverged");
  // RK45 rejects overflowing trial stages rather than reporting them, until the step is below its minimum.
  auto fresh = system.CreateDefaultContext();
  RungeKutta45Integrator rk45(0.5);
  CAIRN_EXPECT_THROWS_WITH(rk45.Step(system, fresh.get(), 10.0), std::runtime_error, "step size fell to",
                           "below the minimum 1e-14");
}

}  // namespace
}  // namespace cairn::systems
