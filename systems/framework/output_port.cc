#include "cairn/common/number_text.h"
#include "cairn/systems/framework/output_port.h"

#include <stdexcept>
#include <utility>

#include "cairn/common/nice_type_name.h"
#include "cairn/systems/framework/system.h"

namespace cairn::systems {

OutputPort::OutputPort(const System* system, int index, std::string name, PortDataType data_type, int size,
                       std::unique_ptr<AbstractValue> model_value)
    : system_(system),
      index_(index),
      name_(std::move(name)),
      data_type_(data_type),
      size_(size),
      model_value_(std::move(model_value)) {}

const AbstractValue& OutputPort::EvalAbstract(const Context& context) const {
  system_->ValidateContext(context);
  return system_->DoEvalOutput(context, index_);
}

void OutputPort::Calc(const Context& context, AbstractValue* value) const {
  system_->ValidateContext(context);
  if (value == nullptr) throw std::invalid_argument("OutputPort::Calc: value must not be null; use Allocate().");
  if (value->type_info() != model_value_->type_info()) {
    throw std::invalid_argument("OutputPort::Calc for the " + GetFullDescription() + " was given storage of type " +
                                value->GetNiceTypeName() + "; use Allocate().");
  }
  system_->DoCalcOutput(context, index_, value);
}

void OutputPort::ThrowTypeMismatch(const std::type_info& requested) const {
  throw std::logic_error("The " + GetFullDescription() + " carries " + model_value_->GetNiceTypeName() +
                         " but was evaluated as " + NiceTypeName(requested) + "; use Eval<" +
                         model_value_->GetNiceTypeName() + ">().");
}

std::string OutputPort::GetFullDescription() const {
  return "output port '" + name_ + "' of system '" + system_->GetPathName() + "'";
}

std::string OutputPort::GetTypeDescription() const {
  if (data_type_ == PortDataType::kVector) return "vector of size " + cairn::FormatShort(size_);
  return "abstract value of type " + model_value_->GetNiceTypeName();
}

}  // namespace cairn::systems
