#pragma once

#include <functional>

#include <Eigen/Core>

#include "cairn/systems/framework/leaf_system.h"

namespace cairn::systems {

/// Wraps a function y = f(t, u) as a system, for quick experiments and tests.
///
/// | port | type | meaning |
/// |---|---|---|
/// | input `u` (only if input_size > 0) | vector of size input_size | argument |
/// | output `y` | vector of size output_size | f(t, u) (direct feedthrough) |
class FunctionSystem final : public LeafSystem {
 public:
  using Function = std::function<Eigen::VectorXd(double time, const Eigen::VectorXd& u)>;

  /// `function` must return vectors of `output_size`; with input_size = 0 it receives an empty u.
  FunctionSystem(int input_size, int output_size, Function function);

 private:
  void CalcOutput(const Context& context, Eigen::VectorXd* y) const;
  Function function_;
};

}  // namespace cairn::systems
