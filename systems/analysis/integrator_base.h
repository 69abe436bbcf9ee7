#pragma once

#include <cstdint>
#include <string>

#include <Eigen/Core>

#include "cairn/systems/framework/context.h"
#include "cairn/systems/framework/system.h"

namespace cairn::systems {

/// Advances the continuous state of a system's context in time. The Simulator asks for one step at a time,
/// never past the next event, so events land exactly on their times.
///
/// Fixed-step integrators take steps of maximum_step_size(), stretching the last step by up to 1% instead of
/// leaving a sliver; error-controlled ones choose their step from the target accuracy.
class IntegratorBase {
 public:
  virtual ~IntegratorBase();
  IntegratorBase(const IntegratorBase&) = delete;
  IntegratorBase& operator=(const IntegratorBase&) = delete;

  /// Short name for messages and logs ("rk4", ...).
  virtual std::string name() const = 0;

  /// Advances `context` (time and continuous state) by one step towards `t_max` (finite, > current time) and
  /// returns the time reached, which is `t_max` exactly when the step ends there. Throws std::invalid_argument
  /// when the maximum step size cannot advance time at the current time (t + h == t in double precision, which
  /// would otherwise repeat the step forever), and std::runtime_error when the step leaves a non-finite state
  /// (the simulation diverged) or did not advance time.
  double Step(const System& system, Context* context, double t_max);

  /// The largest step; throws std::invalid_argument unless finite and > 0.
  void set_maximum_step_size(double h);
  double maximum_step_size() const { return maximum_step_size_; }

  /// Whether the integrator controls its local error (then set_target_accuracy applies).
  virtual bool supports_error_control() const { return false; }
  /// Relative and absolute tolerance of the local error per step; throws for integrators without error control.
  void set_target_accuracy(double accuracy);
  double target_accuracy() const { return target_accuracy_; }

  int64_t num_steps_taken() const { return num_steps_taken_; }
  int64_t num_derivative_evaluations() const { return num_derivative_evaluations_; }
  int64_t num_step_rejections() const { return num_step_rejections_; }
  void ResetStatistics();

 protected:
  explicit IntegratorBase(double maximum_step_size);

  /// Takes one step from the context's time towards t_max; returns the time reached.
  virtual double DoStep(const System& system, Context* context, double t_max) = 0;

  /// The fixed step from `t` towards `t_max`: maximum_step_size(), or the remainder when it is within 1% more.
  double FixedStepEnd(double t, double t_max) const;
  /// Derivatives at (t, x); sets them in the context first. Counts evaluations.
  void EvalDerivatives(const System& system, Context* context, double t, const Eigen::VectorXd& x,
                       Eigen::VectorXd* xdot);
  /// Writes the continuous state of `context` without the finiteness check of Context::SetContinuousState.
  static void WriteContinuousState(Context* context, const Eigen::VectorXd& x);
  void count_rejection() { ++num_step_rejections_; }

 private:
  double maximum_step_size_;
  double target_accuracy_{1e-6};
  int64_t num_steps_taken_{0};
  int64_t num_derivative_evaluations_{0};
  int64_t num_step_rejections_{0};
};

}  // namespace cairn::systems
