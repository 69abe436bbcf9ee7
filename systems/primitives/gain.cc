#include "cairn/systems/primitives/gain.h"

#include <stdexcept>
#include <string>

namespace cairn::systems {

Gain::Gain(double k, int size) : Gain(Eigen::VectorXd::Constant(size < 0 ? 0 : size, k)) {
  if (size <= 0) throw std::invalid_argument("Gain: size must be positive; got " + std::to_string(size) + ".");
}

Gain::Gain(const Eigen::VectorXd& k) : k_(k) {
  const int size = static_cast<int>(k.size());
  const auto& u = DeclareVectorInputPort("u", size);
  DeclareVectorOutputPort("y", size, &Gain::CalcOutput, {u.ticket()});
}

void Gain::CalcOutput(const Context& context, Eigen::VectorXd* y) const {
  *y = k_.cwiseProduct(get_input_port().Eval<Eigen::VectorXd>(context));
}

}  // namespace cairn::systems
