#pragma once

#include "cairn/systems/analysis/integrator_base.h"

namespace cairn::systems {

/// Classical fourth-order Runge–Kutta with fixed steps. Global error O(h^4).
class RungeKutta4Integrator final : public IntegratorBase {
 public:
  explicit RungeKutta4Integrator(double maximum_step_size);
  std::string name() const override { return "rk4"; }

 private:
  double DoStep(const System& system, Context* context, double t_max) override;
  Eigen::VectorXd x0_, k1_, k2_, k3_, k4_;
};

}  // namespace cairn::systems
