#pragma once

#include "cairn/systems/framework/leaf_system.h"

namespace cairn::systems {

/// Copies its input to its output: a vector of fixed size or any abstract type.
///
/// | port | type | meaning |
/// |---|---|---|
/// | input `u` | vector of size n, or abstract T | signal |
/// | output `y` | same as `u` | u (direct feedthrough) |
class PassThrough final : public LeafSystem {
 public:
  /// A vector pass-through of `size` elements.
  explicit PassThrough(int size);
  /// An abstract pass-through for values of `model_value`'s type.
  explicit PassThrough(const AbstractValue& model_value);
};

}  // namespace cairn::systems
