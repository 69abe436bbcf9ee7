#include "examples/systems/pendulum_plant.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include "cairn/common/number_text.h"

namespace cairn::examples {

PendulumPlant::PendulumPlant(const PendulumParameters& p) {
  if (!(p.mass > 0.0) || !(p.length > 0.0) || !(p.damping >= 0.0) || !(p.gravity >= 0.0)) {
    throw std::invalid_argument("PendulumPlant: need mass > 0, length > 0, damping >= 0 and gravity >= 0; got mass " +
                                cairn::FormatShort(p.mass) + ", length " + cairn::FormatShort(p.length) + ", damping " +
                                cairn::FormatShort(p.damping) + ", gravity " + cairn::FormatShort(p.gravity) + ".");
  }
  DeclareVectorInputPort("torque", 1);
  DeclareContinuousState(Eigen::Vector2d::Zero());
  DeclareNumericParameter(Eigen::Vector4d(p.mass, p.length, p.damping, p.gravity));
  DeclareVectorOutputPort(
      "state", 2, [](const systems::Context& context, Eigen::VectorXd* y) { *y = context.get_continuous_state_vector(); },
      {xc_ticket()});
}

PendulumParameters PendulumPlant::GetParameters(const systems::Context& context) const {
  ValidateContext(context);
  const Eigen::VectorXd& v = context.get_numeric_parameter(0);
  return PendulumParameters{v[0], v[1], v[2], v[3]};
}

double PendulumPlant::CalcTotalEnergy(const systems::Context& context) const {
  const PendulumParameters p = GetParameters(context);
  const auto x = context.get_continuous_state_vector();
  const double kinetic = 0.5 * p.mass * p.length * p.length * x[1] * x[1];
  const double potential = p.mass * p.gravity * p.length * (1.0 - std::cos(x[0]));
  return kinetic + potential;
}

void PendulumPlant::DoCalcTimeDerivatives(const systems::Context& context,
                                          Eigen::Ref<Eigen::VectorXd> derivatives) const {
  const Eigen::VectorXd& v = context.get_numeric_parameter(0);
  const double m = v[0], l = v[1], b = v[2], g = v[3];
  const auto x = context.get_continuous_state_vector();
  const double torque = get_input_port().Eval<Eigen::VectorXd>(context)[0];
  derivatives[0] = x[1];
  derivatives[1] = (torque - b * x[1] - m * g * l * std::sin(x[0])) / (m * l * l);
}

}  // namespace cairn::examples
