#include "cairn/common/number_text.h"
#include "cairn/systems/framework/input_port.h"

#include <stdexcept>
#include <utility>

#include "cairn/common/nice_type_name.h"
#include "cairn/systems/framework/system.h"

namespace cairn::systems {

InputPort::InputPort(const System* system, int index, std::string name, PortDataType data_type, int size,
                     std::unique_ptr<AbstractValue> model_value, DependencyTicket ticket)
    : system_(system),
      index_(index),
      name_(std::move(name)),
      data_type_(data_type),
      size_(size),
      model_value_(std::move(model_value)),
      ticket_(ticket) {}

const AbstractValue& InputPort::EvalAbstract(const Context& context) const {
  system_->ValidateContext(context);
  return context.EvalInput(index_);
}

bool InputPort::HasValue(const Context& context) const {
  system_->ValidateContext(context);
  const auto& slot = context.inputs_[index_];
  if (slot.fixed_value || slot.source_system != nullptr) return true;
  if (slot.parent_port >= 0) {
    return context.parent_->system_->get_input_port(slot.parent_port).HasValue(*context.parent_);
  }
  return false;
}

void InputPort::ValidateValue(const AbstractValue& value) const {
  if (value.type_info() != model_value_->type_info()) {
    throw std::invalid_argument("Cannot give the " + GetFullDescription() + " (" + GetTypeDescription() +
                                ") a value of type " + value.GetNiceTypeName() + "; pass a " +
                                model_value_->GetNiceTypeName() + ".");
  }
  if (data_type_ == PortDataType::kVector) {
    const auto actual = value.get_value<Eigen::VectorXd>().size();
    if (actual != size_) {
      throw std::invalid_argument("Cannot give the " + GetFullDescription() + " (" + GetTypeDescription() +
                                  ") a vector of size " + cairn::FormatShort(actual) + ".");
    }
  }
}

void InputPort::FixAbstractValue(Context* context, const AbstractValue& value) const {
  if (context == nullptr) throw std::invalid_argument("FixValue: context must not be null.");
  system_->ValidateContext(*context);
  ValidateValue(value);
  auto& slot = context->inputs_[index_];
  if (slot.source_system != nullptr || slot.parent_port >= 0) {
    throw std::logic_error("Cannot fix the " + GetFullDescription() + ": in this diagram it is " +
                           slot.source_description +
                           ". FixValue applies to unconnected ports; fix the diagram's exported input instead, or "
                           "test the system alone with its own CreateDefaultContext().");
  }
  if (slot.fixed_value) {
    slot.fixed_value->SetFrom(value);
  } else {
    slot.fixed_value = value.Clone();
  }
  context->NoteChange(ticket_.index());
}

void InputPort::ThrowTypeMismatch(const std::type_info& requested) const {
  throw std::logic_error("The " + GetFullDescription() + " carries " + model_value_->GetNiceTypeName() +
                         " but was evaluated as " + NiceTypeName(requested) + "; use Eval<" +
                         model_value_->GetNiceTypeName() + ">().");
}

std::string InputPort::GetFullDescription() const {
  return "input port '" + name_ + "' of system '" + system_->GetPathName() + "'";
}

std::string InputPort::GetTypeDescription() const {
  if (data_type_ == PortDataType::kVector) return "vector of size " + cairn::FormatShort(size_);
  return "abstract value of type " + model_value_->GetNiceTypeName();
}

}  // namespace cairn::systems
