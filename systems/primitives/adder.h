#pragma once

#include "cairn/systems/framework/leaf_system.h"

namespace cairn::systems {

/// Sums its inputs.
///
/// | port | type | meaning |
/// |---|---|---|
/// | inputs `u0` ... `u<n-1>` | vector of size m | addends |
/// | output `sum` | vector of size m | u0 + ... + u<n-1> (direct feedthrough) |
class Adder final : public LeafSystem {
 public:
  Adder(int num_inputs, int size);

 private:
  void CalcSum(const Context& context, Eigen::VectorXd* sum) const;
};

}  // namespace cairn::systems
