#include "cairn/systems/primitives/integrator.h"

#include <stdexcept>
#include <string>

namespace cairn::systems {

Integrator::Integrator(int size) : Integrator(Eigen::VectorXd::Zero(size < 1 ? 1 : size)) {
  if (size < 1) throw std::invalid_argument("Integrator: size must be positive; got " + std::to_string(size) + ".");
}

Integrator::Integrator(const Eigen::VectorXd& initial_value) {
  const int size = static_cast<int>(initial_value.size());
  if (size < 1) throw std::invalid_argument("Integrator: the initial value must not be empty.");
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
