#pragma once

#include <Eigen/Core>

#include "cairn/systems/framework/leaf_system.h"

namespace cairn::systems {

/// Samples its input every `period` seconds (at t = 0, period, 2 period, ...) and holds it. The output depends
/// only on the held sample, never on the current input, so a ZeroOrderHold breaks algebraic loops.
///
/// | port | type | meaning |
/// |---|---|---|
/// | input `u` | vector of size n, or abstract T | signal to sample |
/// | output `y` | same as `u` | the last sample (initially zero, or the model value) |
///
/// State: the held sample (discrete state for vectors, abstract state for abstract values).
class ZeroOrderHold final : public LeafSystem {
 public:
  /// A vector hold of `size` elements. Throws std::invalid_argument unless `period` is finite and > 0.
  ZeroOrderHold(double period, int size);
  /// An abstract hold for values of `model_value`'s type, holding `model_value` until the first sample.
  ZeroOrderHold(double period, const AbstractValue& model_value);

  double period() const { return period_; }

 private:
  double period_;
};

}  // namespace cairn::systems
