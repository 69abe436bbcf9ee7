#pragma once

#include "cairn/systems/framework/leaf_system.h"

namespace cairn::examples {

/// Proportional–derivative control of one joint: τ = kp (θ_desired − θ) − kd θ'.
///
/// | port | type | meaning |
/// |---|---|---|
/// | input `state` | vector of size 2 | measured (θ, θ') |
/// | output `torque` | vector of size 1 | τ [N m] (direct feedthrough) |
///
/// Parameters: numeric (kp, kd, θ_desired).
class PdController final : public systems::LeafSystem {
 public:
  PdController(double kp, double kd, double theta_desired);

 private:
  void CalcTorque(const systems::Context& context, Eigen::VectorXd* torque) const;
};

}  // namespace cairn::examples
