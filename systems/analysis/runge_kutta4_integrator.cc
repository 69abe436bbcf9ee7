#include "cairn/systems/analysis/runge_kutta4_integrator.h"

namespace cairn::systems {

RungeKutta4Integrator::RungeKutta4Integrator(double maximum_step_size) : IntegratorBase(maximum_step_size) {}

double RungeKutta4Integrator::DoStep(const System& system, Context* context, double t_max) {
  const double t0 = context->get_time();
  const double t1 = FixedStepEnd(t0, t_max);
  const double h = t1 - t0;
  x0_ = context->get_continuous_state_vector();
  EvalDerivatives(system, context, t0, x0_, &k1_);
  EvalDerivatives(system, context, t0 + 0.5 * h, x0_ + 0.5 * h * k1_, &k2_);
  EvalDerivatives(system, context, t0 + 0.5 * h, x0_ + 0.5 * h * k2_, &k3_);
  EvalDerivatives(system, context, t1, x0_ + h * k3_, &k4_);
  context->SetTime(t1);
  WriteContinuousState(context, x0_ + (h / 6.0) * (k1_ + 2.0 * k2_ + 2.0 * k3_ + k4_));
  return t1;
}

}  // namespace cairn::systems
