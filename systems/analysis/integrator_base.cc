#include "cairn/systems/analysis/integrator_base.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace cairn::systems {

IntegratorBase::IntegratorBase(double maximum_step_size) : maximum_step_size_(1.0) {
  set_maximum_step_size(maximum_step_size);
}

IntegratorBase::~IntegratorBase() = default;

void IntegratorBase::set_maximum_step_size(double h) {
  if (!(h > 0.0) || !std::isfinite(h)) {
    throw std::invalid_argument("The maximum step size must be finite and > 0; got " + std::to_string(h) + ".");
  }
  maximum_step_size_ = h;
}

void IntegratorBase::set_target_accuracy(double accuracy) {
  if (!supports_error_control()) {
    throw std::logic_error("Integrator '" + name() +
                           "' has no error control, so a target accuracy does not apply; set its maximum step size, "
                           "or use RungeKutta45Integrator.");
  }
  if (!(accuracy > 0.0) || !(accuracy < 1.0)) {
    throw std::invalid_argument("The target accuracy must be in (0, 1); got " + std::to_string(accuracy) + ".");
  }
  target_accuracy_ = accuracy;
}

void IntegratorBase::ResetStatistics() {
  num_steps_taken_ = 0;
  num_derivative_evaluations_ = 0;
  num_step_rejections_ = 0;
}

double IntegratorBase::Step(const System& system, Context* context, double t_max) {
  if (context == nullptr) throw std::invalid_argument("IntegratorBase::Step: context must not be null.");
  system.ValidateContext(*context);
  if (!(t_max > context->get_time())) {
    throw std::invalid_argument("IntegratorBase::Step: t_max = " + std::to_string(t_max) +
                                " is not after the current time " + std::to_string(context->get_time()) + ".");
  }
  const double reached = DoStep(system, context, t_max);
  ++num_steps_taken_;
  return reached;
}

double IntegratorBase::FixedStepEnd(double t, double t_max) const {
  return (t_max - t <= 1.01 * maximum_step_size_) ? t_max : t + maximum_step_size_;
}

void IntegratorBase::EvalDerivatives(const System& system, Context* context, double t, const Eigen::VectorXd& x,
                                     Eigen::VectorXd* xdot) {
  context->SetTime(t);
  context->SetContinuousState(x);
  system.CalcTimeDerivatives(*context, xdot);
  ++num_derivative_evaluations_;
}

}  // namespace cairn::systems
