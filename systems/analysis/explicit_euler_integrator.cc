#include "cairn/systems/analysis/explicit_euler_integrator.h"

namespace cairn::systems {

ExplicitEulerIntegrator::ExplicitEulerIntegrator(double maximum_step_size) : IntegratorBase(maximum_step_size) {}

double ExplicitEulerIntegrator::DoStep(const System& system, Context* context, double t_max) {
  const double t0 = context->get_time();
  const double t1 = FixedStepEnd(t0, t_max);
  x0_ = context->get_continuous_state_vector();
  EvalDerivatives(system, context, t0, x0_, &xdot_);
  context->SetTime(t1);
  WriteContinuousState(context, x0_ + (t1 - t0) * xdot_);
  return t1;
}

}  // namespace cairn::systems
