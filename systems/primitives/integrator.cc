#include "cairn/systems/primitives/integrator.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include "cairn/common/number_text.h"

namespace cairn::systems {

Integrator::Integrator(int size) : Integrator(Eigen::VectorXd::Zero(size < 1 ? 1 : size)) {
  if (size < 1) throw std::invalid_argument("Integrator: size must be positive; got " + std::to_string(size) + ".");
}

Integrator::Integrator(const Eigen::VectorXd& initial_value) {
  const int size = static_cast<int>(initial_value.size());
  if (size < 1) throw std::invalid_argument("Integrator: the initial value must not be empty.");
  for (int i = 0; i < size; ++i) {
    if (!std::isfinite(initial_value[i])) {
      throw std::invalid_argument("Integrator: initial value element " + std::to_string(i) + " is " +
                                  FormatShort(initial_value[i]) + "; it must be finite.");
    }
  }
  DeclareVectorInputPort("u", size);
  DeclareContinuousState(initial_value);
  DeclareVectorOutputPort(
      "y", size, [](const Context& context, Eigen::VectorXd* y) { *y = context.get_continuous_state_vector(); },
      {xc_ticket()});
}

void Integrator::DoCalcTimeDerivatives(const Context& context, Eigen::Ref<Eigen::VectorXd> derivatives) const {
  derivatives = get_input_port().Eval<Eigen::VectorXd>(context);
}

}  // namespace cairn::systems
