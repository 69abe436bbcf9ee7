#include "cairn/common/number_text.h"
#include "cairn/systems/primitives/pass_through.h"

#include <stdexcept>
#include <string>

namespace cairn::systems {

PassThrough::PassThrough(int size) {
  if (size < 1) throw std::invalid_argument("PassThrough: size must be positive; got " + cairn::FormatShort(size) + ".");
  const auto& u = DeclareVectorInputPort("u", size);
  DeclareVectorOutputPort(
      "y", size, [this](const Context& context, Eigen::VectorXd* y) { *y = get_input_port().Eval<Eigen::VectorXd>(context); },
      {u.ticket()});
}

PassThrough::PassThrough(const AbstractValue& model_value) {
  const auto& u = DeclareAbstractInputPort("u", model_value);
  DeclareAbstractOutputPort(
      "y", model_value,
      [this](const Context& context, AbstractValue* y) { y->SetFrom(get_input_port().EvalAbstract(context)); },
      {u.ticket()});
}

}  // namespace cairn::systems
