#include "cairn/systems/analysis/integrator_base.h"

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "cairn/common/number_text.h"

namespace cairn::systems {

IntegratorBase::IntegratorBase(double maximum_step_size) : maximum_step_size_(1.0) {
  set_maximum_step_size(maximum_step_size);
}

IntegratorBase::~IntegratorBase() = default;

void IntegratorBase::set_maximum_step_size(double h) {
  if (!(h > 0.0) || !std::isfinite(h)) {
    throw std::invalid_argument("The maximum step size must be finite and > 0; got " + FormatShort(h) + ".");
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
    throw std::invalid_argument("The target accuracy must be in (0, 1); got " + FormatShort(accuracy) + ".");
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
  const double t = context->get_time();
  if (!(t_max > t) || !std::isfinite(t_max)) {
    throw std::invalid_argument("IntegratorBase::Step: t_max = " + FormatShort(t_max) +
                                " is not after the current time " + FormatShort(t) + ", or not finite.");
  }
  // A step that cannot move time would be repeated forever by a caller advancing to t_max.
  if (!(t + maximum_step_size_ > t) && !(t_max - t <= 1.01 * maximum_step_size_)) {
    const double spacing = std::nextafter(t, std::numeric_limits<double>::infinity()) - t;
    throw std::invalid_argument("Integrator '" + name() + "': the maximum step size " + FormatShort(maximum_step_size_) +
                                " s cannot advance time from t = " + FormatShort(t) +
                                " (t + h == t: doubles there are " + FormatShort(spacing) +
                                " s apart); set a maximum step size many times larger.");
  }
  const double reached = DoStep(system, context, t_max);
  ++num_steps_taken_;
  if (!(reached > t)) {
    throw std::runtime_error("Integrator '" + name() + "': the step from t = " + FormatShort(t) +
                             " did not advance time; raise the maximum step size.");
  }
  const auto x = context->get_continuous_state_vector();
  for (Eigen::Index i = 0; i < x.size(); ++i) {
    if (!std::isfinite(x[i])) {
      throw std::runtime_error("Integrator '" + name() + "': the continuous state of '" + system.GetPathName() +
                               "' became non-finite (element " + std::to_string(i) + " = " + FormatShort(x[i]) +
                               ") in the step from t = " + FormatShort(t) + " to " + FormatShort(reached) +
                               "; the simulation diverged: lower the maximum step size, use an error-controlled "
                               "integrator (rk45), or check the dynamics and gains.");
    }
  }
  return reached;
}

double IntegratorBase::FixedStepEnd(double t, double t_max) const {
  return (t_max - t <= 1.01 * maximum_step_size_) ? t_max : t + maximum_step_size_;
}

void IntegratorBase::EvalDerivatives(const System& system, Context* context, double t, const Eigen::VectorXd& x,
                                     Eigen::VectorXd* xdot) {
  context->SetTime(t);
  WriteContinuousState(context, x);
  system.CalcTimeDerivatives(*context, xdot);
  ++num_derivative_evaluations_;
}

void IntegratorBase::WriteContinuousState(Context* context, const Eigen::VectorXd& x) {
  // Not SetContinuousState: that refuses non-finite values from users, while a trial stage of an adaptive step
  // may legitimately overflow (the step is then rejected), and Step() reports a diverged result itself.
  context->get_mutable_continuous_state_vector() = x;
}

}  // namespace cairn::systems
