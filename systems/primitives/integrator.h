#pragma once

#include <Eigen/Core>

#include "cairn/systems/framework/leaf_system.h"

namespace cairn::systems {

/// Continuous integrator: x' = u, y = x.
///
/// | port | type | meaning |
/// |---|---|---|
/// | input `u` | vector of size n | rate |
/// | output `y` | vector of size n | the integral x (no direct feedthrough) |
///
/// State: continuous x of size n, initially zero (or `initial_value`).
class Integrator final : public LeafSystem {
 public:
  explicit Integrator(int size);
  /// Starts at `initial_value` (not empty, every element finite; throws std::invalid_argument otherwise).
  explicit Integrator(const Eigen::VectorXd& initial_value);

 private:
  void DoCalcTimeDerivatives(const Context& context, Eigen::Ref<Eigen::VectorXd> derivatives) const override;
};

}  // namespace cairn::systems
