#pragma once

#include <Eigen/Core>

#include "cairn/systems/framework/leaf_system.h"

namespace cairn::systems::test {

/// A leaf system exercising every kind of declaration; outputs count how often they are computed.
///
/// | port | type | meaning |
/// |---|---|---|
/// | input `u` | vector of size 2 | signal |
/// | input `label` | abstract std::string | a label |
/// | output `sum` | vector of size 2 | u + xd + p (prerequisites u, xd, p) |
/// | output `time` | vector of size 1 | time (prerequisite time only) |
/// | output `everything` | vector of size 1 | t + |u| + xc (default prerequisites) |
/// | output `text` | abstract std::string | label + "!" |
class KitchenSink final : public LeafSystem {
 public:
  KitchenSink() {
    const auto& u = DeclareVectorInputPort("u", 2);
    const auto& label = DeclareAbstractInputPort("label", Value<std::string>("none"));
    DeclareContinuousState(Eigen::Vector2d(1.0, -1.0));
    const int xd = DeclareDiscreteState(Eigen::Vector2d(10.0, 20.0));
    DeclareAbstractState(Value<int>(42));
    const int p = DeclareNumericParameter(Eigen::Vector2d(0.5, 0.25));
    DeclareAbstractParameter(Value<std::string>("param"));
    DeclareVectorOutputPort(
        "sum", 2,
        [this](const Context& context, Eigen::VectorXd* y) {
          *y = get_input_port(0).Eval<Eigen::VectorXd>(context) + context.get_discrete_state(0) +
               context.get_numeric_parameter(0);
        },
        {u.ticket(), discrete_state_ticket(xd), numeric_parameter_ticket(p)});
    DeclareVectorOutputPort(
        "time", 1, [](const Context& context, Eigen::VectorXd* y) { (*y)[0] = context.get_time(); }, {time_ticket()});
    DeclareVectorOutputPort("everything", 1, [this](const Context& context, Eigen::VectorXd* y) {
      (*y)[0] = context.get_time() + get_input_port(0).Eval<Eigen::VectorXd>(context).norm() +
                context.get_continuous_state_vector().sum();
    });
    DeclareAbstractOutputPort(
        "text", Value<std::string>(),
        [this](const Context& context, AbstractValue* y) {
          y->set_value<std::string>(get_input_port(1).Eval<std::string>(context) + "!");
        },
        {label.ticket()});
  }

 private:
  void DoCalcTimeDerivatives(const Context& context, Eigen::Ref<Eigen::VectorXd> derivatives) const override {
    derivatives = -context.get_continuous_state_vector();
  }
};

}  // namespace cairn::systems::test
