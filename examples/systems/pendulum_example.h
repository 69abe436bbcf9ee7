#pragma once

#include <memory>
#include <string>

#include <Eigen/Core>

#include "cairn/systems/framework/diagram.h"
#include "examples/systems/pendulum_plant.h"

namespace cairn::examples {

/// Settings of the pendulum example: a damped pendulum held at a target angle by a PD controller that sees the
/// state through a ZeroOrderHold (a discrete controller), logged, simulated.
struct PendulumExampleOptions {
  PendulumParameters plant;
  double kp{5.0};                ///< N m / rad
  double kd{0.5};                ///< N m s / rad
  double theta_desired{0.7853981633974483};  ///< rad (45 degrees)
  double control_period{0.001};  ///< s, the ZeroOrderHold's sampling period
  Eigen::Vector2d initial_state{0.0, 0.0};
  double duration{10.0};         ///< s
  std::string integrator{"rk4"};  ///< "euler", "rk4" or "rk45"
  double max_step{0.001};        ///< s
  double accuracy{1e-8};         ///< rk45 only
  double log_period{0.01};       ///< s; 0 logs every step
};

/// The example's diagram: plant.state -> hold -> controller -> plant.torque, plant.state -> logger.
/// Subsystems are named "plant", "hold", "controller" and "logger".
std::unique_ptr<systems::Diagram> BuildPendulumDiagram(const PendulumExampleOptions& options);

/// What a run produced.
struct PendulumRun {
  Eigen::Vector2d final_state;
  double final_time{0.0};
  double final_energy{0.0};
  /// The equilibrium the controller should settle at: kp (θd − θ) = m g l sin θ.
  double predicted_equilibrium{0.0};
  int64_t steps{0};
  Eigen::VectorXd log_times;
  Eigen::MatrixXd log_states;  ///< 2 x samples
};

/// Builds and simulates the example; writes the log as CSV to `csv_path` unless it is empty.
PendulumRun RunPendulumExample(const PendulumExampleOptions& options, const std::string& csv_path = "");

}  // namespace cairn::examples
