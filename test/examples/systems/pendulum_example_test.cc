#include "examples/systems/pendulum_example.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

namespace cairn::examples {
namespace {

// Mean period from the upward zero crossings of θ − θ_eq, each located by linear interpolation.
double MeasuredPeriod(const PendulumRun& run, double equilibrium) {
  std::vector<double> crossings;
  for (int k = 1; k < run.log_times.size(); ++k) {
    const double a = run.log_states(0, k - 1) - equilibrium;
    const double b = run.log_states(0, k) - equilibrium;
    if (a < 0.0 && b >= 0.0) {
      const double t0 = run.log_times[k - 1];
      const double t1 = run.log_times[k];
      crossings.push_back(t0 + (t1 - t0) * (-a) / (b - a));
    }
  }
  EXPECT_GE(crossings.size(), 3u);
  return (crossings.back() - crossings.front()) / static_cast<double>(crossings.size() - 1);
}

// Damped small-angle period of m l² θ'' + c θ' + k θ = 0.
double AnalyticPeriod(double inertia, double damping, double stiffness) {
  const double omega_n2 = stiffness / inertia;
  const double decay = damping / (2.0 * inertia);
  return 2.0 * M_PI / std::sqrt(omega_n2 - decay * decay);
}

TEST(PendulumExampleTest, FreeSmallAngleOscillationHasTheAnalyticPeriod) {
  PendulumExampleOptions options;
  options.kp = 0.0;
  options.kd = 0.0;
  options.theta_desired = 0.0;
  options.initial_state = Eigen::Vector2d(0.02, 0.0);
  options.duration = 5.0;
  options.log_period = 0.0;  // Every 1 ms step.
  const PendulumRun run = RunPendulumExample(options);
  const PendulumParameters& p = options.plant;
  const double expected = AnalyticPeriod(p.mass * p.length * p.length, p.damping, p.mass * p.gravity * p.length);
  EXPECT_NEAR(MeasuredPeriod(run, 0.0), expected, 0.01 * expected);
}

TEST(PendulumExampleTest, ClosedLoopSmallAnglePeriodMatchesTheLinearisedLoop) {
  PendulumExampleOptions options;
  options.theta_desired = 0.0;
  options.kp = 2.0;
  options.kd = 0.05;
  options.initial_state = Eigen::Vector2d(0.02, 0.0);
  options.duration = 5.0;
  options.log_period = 0.0;
  const PendulumRun run = RunPendulumExample(options);
  const PendulumParameters& p = options.plant;
  const double expected = AnalyticPeriod(p.mass * p.length * p.length, p.damping + options.kd,
                                         p.mass * p.gravity * p.length + options.kp);
  EXPECT_NEAR(MeasuredPeriod(run, 0.0), expected, 0.01 * expected);
}

TEST(PendulumExampleTest, SettlesAtThePdEquilibriumAndRk45AgreesWithRk4) {
  PendulumExampleOptions options;
  const PendulumRun rk4 = RunPendulumExample(options);
  EXPECT_NEAR(rk4.final_state[0], rk4.predicted_equilibrium, 1e-4);
  EXPECT_NEAR(rk4.final_state[1], 0.0, 1e-3);

  options.integrator = "rk45";
  options.max_step = 0.001;  // Events every 1 ms bound the step anyway; RK45 controls the error inside it.
  options.accuracy = 1e-10;
  const PendulumRun rk45 = RunPendulumExample(options);
  EXPECT_NEAR(rk45.final_state[0], rk4.final_state[0], 1e-8);
  EXPECT_NEAR(rk45.final_state[1], rk4.final_state[1], 1e-8);
}

TEST(PendulumExampleTest, WritesTheLogAsCsv) {
  PendulumExampleOptions options;
  options.duration = 0.1;
  const auto path = std::filesystem::temp_directory_path() / "cairn_pendulum_example_test.csv";
  const PendulumRun run = RunPendulumExample(options, path.string());
  std::ifstream in(path);
  std::string header;
  std::getline(in, header);
  EXPECT_EQ(header, "time,theta,theta_dot");
  int rows = 0;
  for (std::string line; std::getline(in, line);) ++rows;
  EXPECT_EQ(rows, run.log_times.size());
  EXPECT_EQ(rows, 11);
  std::filesystem::remove(path);
}

TEST(PendulumExampleTest, RejectsBadOptions) {
  PendulumExampleOptions options;
  options.integrator = "leapfrog";
  EXPECT_THROW(RunPendulumExample(options), std::invalid_argument);
  options.integrator = "rk4";
  options.duration = -1.0;
  EXPECT_THROW(RunPendulumExample(options), std::invalid_argument);
  options.duration = 1.0;
  options.plant.mass = 0.0;
  EXPECT_THROW(RunPendulumExample(options), std::invalid_argument);
}

}  // namespace
}  // namespace cairn::examples
