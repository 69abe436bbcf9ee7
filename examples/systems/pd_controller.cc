#include "examples/systems/pd_controller.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include "cairn/common/number_text.h"

namespace cairn::examples {

PdController::PdController(double kp, double kd, double theta_desired) {
  if (!(kp >= 0.0) || !(kd >= 0.0) || !std::isfinite(theta_desired)) {
    throw std::invalid_argument("PdController: need kp >= 0, kd >= 0 and a finite target; got kp " +
                                cairn::FormatShort(kp) + ", kd " + cairn::FormatShort(kd) + ", target " +
                                cairn::FormatShort(theta_desired) + ".");
  }
  const auto& state = DeclareVectorInputPort("state", 2);
  const int gains = DeclareNumericParameter(Eigen::Vector3d(kp, kd, theta_desired));
  DeclareVectorOutputPort("torque", 1, &PdController::CalcTorque, {state.ticket(), numeric_parameter_ticket(gains)});
}

void PdController::CalcTorque(const systems::Context& context, Eigen::VectorXd* torque) const {
  const Eigen::VectorXd& gains = context.get_numeric_parameter(0);
  const Eigen::VectorXd& x = get_input_port().Eval<Eigen::VectorXd>(context);
  (*torque)[0] = gains[0] * (gains[2] - x[0]) - gains[1] * x[1];
}

}  // namespace cairn::examples
