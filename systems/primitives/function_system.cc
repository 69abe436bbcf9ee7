#include "cairn/common/number_text.h"
#include "cairn/systems/primitives/function_system.h"

#include <stdexcept>
#include <string>
#include <utility>

namespace cairn::systems {

FunctionSystem::FunctionSystem(int input_size, int output_size, Function function) : function_(std::move(function)) {
  if (input_size < 0 || output_size < 1) {
    throw std::invalid_argument("FunctionSystem: needs input_size >= 0 and output_size >= 1; got " +
                                cairn::FormatShort(input_size) + " and " + cairn::FormatShort(output_size) + ".");
  }
  if (!function_) throw std::invalid_argument("FunctionSystem: the function is empty.");
  if (input_size > 0) DeclareVectorInputPort("u", input_size);
  DeclareVectorOutputPort("y", output_size, &FunctionSystem::CalcOutput);
}

void FunctionSystem::CalcOutput(const Context& context, Eigen::VectorXd* y) const {
  static const Eigen::VectorXd kEmpty;
  const Eigen::VectorXd& u = num_input_ports() > 0 ? get_input_port().Eval<Eigen::VectorXd>(context) : kEmpty;
  Eigen::VectorXd result = function_(context.get_time(), u);
  if (result.size() != y->size()) {
    throw std::logic_error("The function of FunctionSystem '" + GetPathName() + "' returned a vector of size " +
                           cairn::FormatShort(result.size()) + "; the output has size " + cairn::FormatShort(y->size()) +
                           ".");
  }
  *y = std::move(result);
}

}  // namespace cairn::systems
