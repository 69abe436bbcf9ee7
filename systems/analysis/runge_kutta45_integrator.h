#pragma once

#include <array>

#include "cairn/systems/analysis/integrator_base.h"

namespace cairn::systems {

/// Adaptive Dormand–Prince 5(4): a fifth-order step with an embedded fourth-order error estimate. A step is
/// accepted when max_i |e_i| / (a + a |x_i|) <= 1 with a = target_accuracy(); the next step size follows the
/// usual 0.9 err^(-1/5) rule, limited to [0.2, 5] times the last and to maximum_step_size().
class RungeKutta45Integrator final : public IntegratorBase {
 public:
  /// `maximum_step_size` bounds every step; the first trial step is a hundredth of it.
  explicit RungeKutta45Integrator(double maximum_step_size, double target_accuracy = 1e-6);
  std::string name() const override { return "rk45"; }
  bool supports_error_control() const override { return true; }

  /// Steps below this, or too small to advance time at the current time, are refused (the error cannot be met):
  /// throws std::runtime_error naming time and step. `h` must be finite and > 0.
  void set_minimum_step_size(double h);
  double minimum_step_size() const { return minimum_step_size_; }

 private:
  double DoStep(const System& system, Context* context, double t_max) override;
  double minimum_step_size_{1e-14};
  double next_step_{0.0};
  Eigen::VectorXd x0_, x5_, error_;
  std::array<Eigen::VectorXd, 7> k_;
};

}  // namespace cairn::systems
