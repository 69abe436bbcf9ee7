#include "cairn/systems/framework/abstract_value.h"

#include <stdexcept>

#include "cairn/common/nice_type_name.h"

namespace cairn::systems {

AbstractValue::~AbstractValue() = default;

std::string AbstractValue::GetNiceTypeName() const { return NiceTypeName(type_info()); }

void AbstractValue::ThrowTypeMismatch(const std::type_info& requested) const {
  throw std::logic_error("A value of type " + GetNiceTypeName() + " was accessed as " + NiceTypeName(requested) +
                         "; request the type it holds.");
}

}  // namespace cairn::systems
