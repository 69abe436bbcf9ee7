#pragma once

#include "cairn/systems/framework/leaf_system.h"

namespace cairn::systems {

/// Outputs a constant value of any copyable type T. The value is an abstract parameter (per context).
///
/// | port | type | meaning |
/// |---|---|---|
/// | output `y0` | abstract T | the value |
template <typename T>
class ConstantValueSource final : public LeafSystem {
 public:
  explicit ConstantValueSource(const T& value) {
    const int parameter = DeclareAbstractParameter(Value<T>(value));
    DeclareAbstractOutputPort("y0", value, &ConstantValueSource::CalcOutput, {abstract_parameter_ticket(parameter)});
  }

 private:
  void CalcOutput(const Context& context, T* output) const { *output = context.get_abstract_parameter<T>(0); }
};

}  // namespace cairn::systems
