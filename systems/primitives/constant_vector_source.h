#pragma once

#include <Eigen/Core>

#include "cairn/systems/framework/leaf_system.h"

namespace cairn::systems {

/// Outputs a constant vector. The value is a numeric parameter, so it can differ per context.
///
/// | port | type | meaning |
/// |---|---|---|
/// | output `y0` | vector, size of the value | the value |
class ConstantVectorSource final : public LeafSystem {
 public:
  /// Outputs `value`; throws std::invalid_argument if an element is NaN (infinities are allowed).
  explicit ConstantVectorSource(const Eigen::VectorXd& value);

  /// The value in `context`.
  const Eigen::VectorXd& get_value(const Context& context) const { return context.get_numeric_parameter(0); }
  /// Sets the value in `context`; the size must stay the same and no element may be NaN.
  void SetValue(Context* context, const Eigen::VectorXd& value) const;

 private:
  void CalcOutput(const Context& context, Eigen::VectorXd* y) const;
};

}  // namespace cairn::systems
