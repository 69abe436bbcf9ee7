#pragma once

#include "cairn/systems/analysis/integrator_base.h"

namespace cairn::systems {

/// First-order explicit Euler: x(t + h) = x(t) + h f(t, x). Global error O(h).
class ExplicitEulerIntegrator final : public IntegratorBase {
 public:
  explicit ExplicitEulerIntegrator(double maximum_step_size);
  std::string name() const override { return "explicit_euler"; }

 private:
  double DoStep(const System& system, Context* context, double t_max) override;
  Eigen::VectorXd x0_, xdot_;
};

}  // namespace cairn::systems
