#include "cairn/systems/primitives/constant_vector_source.h"

#include <stdexcept>
#include <string>

namespace cairn::systems {

ConstantVectorSource::ConstantVectorSource(const Eigen::VectorXd& value) {
  const int parameter = DeclareNumericParameter(value);
  DeclareVectorOutputPort("y0", static_cast<int>(value.size()), &ConstantVectorSource::CalcOutput,
                          {numeric_parameter_ticket(parameter)});
}

void ConstantVectorSource::SetValue(Context* context, const Eigen::VectorXd& value) const {
  ValidateContext(*context);
  if (value.size() != get_output_port().size()) {
    throw std::invalid_argument("ConstantVectorSource '" + GetPathName() + "' has size " +
                                std::to_string(get_output_port().size()) + "; got a value of size " +
                                std::to_string(value.size()) + ".");
  }
  context->get_mutable_numeric_parameter(0) = value;
}

void ConstantVectorSource::CalcOutput(const Context& context, Eigen::VectorXd* y) const {
  *y = context.get_numeric_parameter(0);
}

}  // namespace cairn::systems
