#pragma once

#include <Eigen/Core>

#include "cairn/systems/framework/leaf_system.h"

namespace cairn::systems {

/// y = k ⊙ u, with a scalar or per-element gain k.
///
/// | port | type | meaning |
/// |---|---|---|
/// | input `u` | vector of size n | signal |
/// | output `y` | vector of size n | k ⊙ u (direct feedthrough) |
class Gain final : public LeafSystem {
 public:
  /// The same gain `k` on all `size` elements. Throws std::invalid_argument unless k is finite and size >= 1.
  Gain(double k, int size);
  /// A gain per element; throws std::invalid_argument for an empty vector or a NaN or infinite element.
  explicit Gain(const Eigen::VectorXd& k);

  const Eigen::VectorXd& k() const { return k_; }

 private:
  void CalcOutput(const Context& context, Eigen::VectorXd* y) const;
  Eigen::VectorXd k_;
};

}  // namespace cairn::systems
