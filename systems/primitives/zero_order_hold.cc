#include "cairn/systems/primitives/zero_order_hold.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include "cairn/common/number_text.h"

namespace cairn::systems {
namespace {

double CheckedPeriod(double period) {
  if (!(period > 0.0) || !std::isfinite(period)) {
    throw std::invalid_argument("ZeroOrderHold: the sampling period must be finite and > 0; got " +
                                FormatShort(period) + ".");
  }
  return period;
}

}  // namespace

ZeroOrderHold::ZeroOrderHold(double period, int size) : period_(CheckedPeriod(period)) {
  if (size < 1) throw std::invalid_argument("ZeroOrderHold: size must be positive; got " + std::to_string(size) + ".");
  DeclareVectorInputPort("u", size);
  const int held = DeclareDiscreteState(Eigen::VectorXd::Zero(size));
  DeclareVectorOutputPort(
      "y", size, [held](const Context& context, Eigen::VectorXd* y) { *y = context.get_discrete_state(held); },
      {discrete_state_ticket(held)});
  DeclarePeriodicDiscreteUpdateEvent(period, 0.0, [this, held](const Context& context, DiscreteValues* next) {
    next->set_value(held, get_input_port().Eval<Eigen::VectorXd>(context));
  });
}

ZeroOrderHold::ZeroOrderHold(double period, const AbstractValue& model_value) : period_(CheckedPeriod(period)) {
  DeclareAbstractInputPort("u", model_value);
  const int held = DeclareAbstractState(model_value);
  DeclareAbstractOutputPort(
      "y", model_value,
      [held](const Context& context, AbstractValue* y) { y->SetFrom(context.get_abstract_state_value(held)); },
      {abstract_state_ticket(held)});
  DeclarePeriodicUnrestrictedUpdateEvent(period, 0.0, [this, held](const Context& context, State* next) {
    next->get_mutable_abstract_state_value(held).SetFrom(get_input_port().EvalAbstract(context));
  });
}

}  // namespace cairn::systems
