#pragma once

#include "cairn/systems/framework/leaf_system.h"

namespace cairn::examples {

/// Physical constants of a point-mass pendulum on a massless rod with viscous joint damping.
struct PendulumParameters {
  double mass{1.0};      ///< kg
  double length{0.5};    ///< m
  double damping{0.1};   ///< N m s / rad
  double gravity{9.81};  ///< m / s^2
};

/// A damped pendulum: m l² θ'' = τ − b θ' − m g l sin θ, θ measured from hanging straight down.
///
/// | port | type | meaning |
/// |---|---|---|
/// | input `torque` | vector of size 1 | joint torque τ [N m] |
/// | output `state` | vector of size 2 | (θ [rad], θ' [rad/s]); no direct feedthrough |
///
/// State: continuous (θ, θ'). Parameters: numeric (mass, length, damping, gravity).
class PendulumPlant final : public systems::LeafSystem {
 public:
  explicit PendulumPlant(const PendulumParameters& parameters = {});

  /// The parameters stored in `context`.
  PendulumParameters GetParameters(const systems::Context& context) const;
  /// Total mechanical energy (kinetic + potential, zero hanging at rest) in `context`.
  double CalcTotalEnergy(const systems::Context& context) const;

 private:
  void DoCalcTimeDerivatives(const systems::Context& context, Eigen::Ref<Eigen::VectorXd> derivatives) const override;
};

}  // namespace cairn::examples
