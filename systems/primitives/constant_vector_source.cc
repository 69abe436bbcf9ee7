#include "cairn/systems/primitives/constant_vector_source.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include "cairn/common/number_text.h"

namespace cairn::systems {
namespace {

// Infinity is allowed (a source may stand for "no limit"); NaN never carries a meaning downstream.
const Eigen::VectorXd& CheckedValue(const Eigen::VectorXd& value, const std::string& who) {
  for (Eigen::Index i = 0; i < value.size(); ++i) {
    if (std::isnan(value[i])) {
      throw std::invalid_argument(who + ": element " + std::to_string(i) + " of the value is NaN; give a number.");
    }
  }
  return value;
}

}  // namespace

ConstantVectorSource::ConstantVectorSource(const Eigen::VectorXd& value) {
  const int parameter = DeclareNumericParameter(CheckedValue(value, "ConstantVectorSource"));
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
  context->get_mutable_numeric_parameter(0) = CheckedValue(value, "ConstantVectorSource '" + GetPathName() + "'");
}

void ConstantVectorSource::CalcOutput(const Context& context, Eigen::VectorXd* y) const {
  *y = context.get_numeric_parameter(0);
}

}  // namespace cairn::systems
