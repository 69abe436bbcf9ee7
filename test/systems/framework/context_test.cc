#include "cairn/systems/framework/context.h"

#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "cairn/systems/framework/diagram_builder.h"
#include "cairn/systems/primitives/integrator.h"
#include "cairn/systems/primitives/pass_through.h"
#include "expect_throws.h"
#include "test_systems.h"

namespace cairn::systems {
namespace {

TEST(ContextTest, CloneCopiesEveryValueIndependently) {
  test::KitchenSink system;
  auto context = system.CreateDefaultContext();
  context->SetTime(2.5);
  context->SetContinuousState(Eigen::Vector2d(7.0, 8.0));
  context->SetDiscreteState(0, Eigen::Vector2d(1.0, 2.0));
  context->get_mutable_abstract_state<int>(0) = 5;
  context->get_mutable_numeric_parameter(0) << 3.0, 4.0;
  system.get_input_port(0).FixValue(context.get(), Eigen::Vector2d(1.0, 1.0));
  const Eigen::VectorXd sum = system.get_output_port(0).Eval<Eigen::VectorXd>(*context);

  auto clone = context->Clone();
  EXPECT_EQ(clone->get_time(), 2.5);
  EXPECT_EQ(clone->get_continuous_state_vector(), Eigen::Vector2d(7.0, 8.0));
  EXPECT_EQ(clone->get_abstract_state<int>(0), 5);
  EXPECT_EQ(system.get_output_port(0).Eval<Eigen::VectorXd>(*clone), sum);
  // The clone's cache came along valid: no recomputation.
  EXPECT_EQ(clone->num_calculations(system.output_port_ticket(0)), 1);

  clone->SetDiscreteState(0, Eigen::Vector2d::Zero());
  EXPECT_EQ(context->get_discrete_state(0), Eigen::Vector2d(1.0, 2.0));
  EXPECT_NE(system.get_output_port(0).Eval<Eigen::VectorXd>(*clone), sum);

  context->SetFrom(*clone);
  EXPECT_EQ(context->get_discrete_state(0), Eigen::Vector2d::Zero());
  EXPECT_EQ(system.get_output_port(0).Eval<Eigen::VectorXd>(*context),
            system.get_output_port(0).Eval<Eigen::VectorXd>(*clone));
}

// An abstract state of doubles and an output that reads only it.
class AbstractHolder final : public LeafSystem {
 public:
  AbstractHolder() {
    const int index = DeclareAbstractState(Value<std::vector<double>>(std::vector<double>(3, 1.0)));
    DeclareAbstractOutputPort(
        "y", Value<std::vector<double>>(),
        [index](const Context& c, AbstractValue* y) { y->SetFrom(c.get_abstract_state_value(index)); },
        {abstract_state_ticket(index)});
  }
};

TEST(ContextTest, ClonedStatesShareAbstractValuesUntilOneSideWrites) {
  AbstractHolder system;
  auto context = system.CreateDefaultContext();
  const OutputPort& y = system.get_output_port(0);
  y.Eval<std::vector<double>>(*context);
  ASSERT_EQ(context->num_calculations(system.output_port_ticket(0)), 1);

  // A state that is cloned and handed back untouched changes nothing, so the output stays cached.
  context->SetState(context->CloneState());
  y.Eval<std::vector<double>>(*context);
  EXPECT_EQ(context->num_calculations(system.output_port_ticket(0)), 1);

  // Writing to the clone copies the value first: the context keeps its own until the state is set.
  State next = context->CloneState();
  next.get_mutable_abstract_state<std::vector<double>>(0)[1] = 7.0;
  EXPECT_EQ(context->get_abstract_state<std::vector<double>>(0)[1], 1.0);
  context->SetState(next);
  EXPECT_EQ(y.Eval<std::vector<double>>(*context)[1], 7.0);
  EXPECT_EQ(context->num_calculations(system.output_port_ticket(0)), 2);

  // After SetState the two share again; writes on either side stay on that side.
  next.get_mutable_abstract_state<std::vector<double>>(0)[1] = 8.0;
  EXPECT_EQ(context->get_abstract_state<std::vector<double>>(0)[1], 7.0);
  State later = context->CloneState();
  context->get_mutable_abstract_state<std::vector<double>>(0)[2] = 9.0;
  EXPECT_EQ(later.abstract_state<std::vector<double>>(0)[2], 1.0);
  // A context clone never shares with its source.
  auto clone = context->Clone();
  clone->get_mutable_abstract_state<std::vector<double>>(0)[0] = 5.0;
  EXPECT_EQ(context->get_abstract_state<std::vector<double>>(0)[0], 1.0);
  EXPECT_EQ(later.abstract_state<std::vector<double>>(0)[0], 1.0);
}

TEST(ContextTest, StateAccessErrorsNameTheSystemAndTheFix) {
  test::KitchenSink system;
  system.set_name("sink");
  auto context = system.CreateDefaultContext();
  CAIRN_EXPECT_THROWS_WITH(context->get_discrete_state(3), std::out_of_range, "'sink' has 1 discrete state",
                           "index 3");
  CAIRN_EXPECT_THROWS_WITH(context->SetContinuousState(Eigen::VectorXd::Zero(5)), std::invalid_argument,
                           "has size 2", "size 5");
  CAIRN_EXPECT_THROWS_WITH(context->SetDiscreteState(0, Eigen::VectorXd::Zero(1)), std::invalid_argument,
                           "has size 2", "size 1");
  CAIRN_EXPECT_THROWS_WITH(context->get_abstract_state<double>(0), std::logic_error, "int", "double");
  CAIRN_EXPECT_THROWS_WITH(context->num_calculations(System::time_ticket()), std::invalid_argument,
                           "not a cached computation");
}

TEST(ContextTest, NonFiniteTimesAndStatesAreRefused) {
  test::KitchenSink system;
  auto context = system.CreateDefaultContext();
  CAIRN_EXPECT_THROWS_WITH(context->SetTime(std::nan("")), std::invalid_argument, "SetTime(nan)", "finite");
  CAIRN_EXPECT_THROWS_WITH(context->SetTime(HUGE_VAL), std::invalid_argument, "SetTime(inf)");
  CAIRN_EXPECT_THROWS_WITH(context->SetContinuousState(Eigen::Vector2d(1.0, std::nan(""))), std::invalid_argument,
                           "SetContinuousState", "element 1 is nan", "finite");
  CAIRN_EXPECT_THROWS_WITH(context->SetDiscreteState(0, Eigen::Vector2d(-HUGE_VAL, 0.0)), std::invalid_argument,
                           "SetDiscreteState(0)", "element 0 is -inf");
  EXPECT_EQ(context->get_continuous_state_vector(), system.CreateDefaultContext()->get_continuous_state_vector());
}

// Declares a continuous and a discrete state from the given initial values.
class StateHolder final : public LeafSystem {
 public:
  StateHolder(const Eigen::VectorXd& continuous, const Eigen::VectorXd& discrete) {
    DeclareContinuousState(continuous);
    DeclareDiscreteState(discrete);
  }
};

TEST(ContextTest, NonFiniteInitialStatesAreRefusedWhereDeclared) {
  CAIRN_EXPECT_THROWS_WITH(StateHolder(Eigen::Vector2d(0.0, HUGE_VAL), Eigen::Vector2d::Zero()),
                           std::invalid_argument, "initial continuous state has element 1 = inf");
  CAIRN_EXPECT_THROWS_WITH(StateHolder(Eigen::Vector2d::Zero(), Eigen::Vector2d(std::nan(""), 0.0)),
                           std::invalid_argument, "initial discrete state has element 0 = nan");
}

TEST(ContextTest, DiagramContextsPointToSubsystemContexts) {
  DiagramBuilder builder;
  auto* a = builder.AddNamedSystem<Integrator>("a", Eigen::Vector2d(1.0, 2.0));
  auto* b = builder.AddNamedSystem<Integrator>("b", Eigen::Vector3d(3.0, 4.0, 5.0));
  auto* pass = builder.AddNamedSystem<PassThrough>("pass", 2);
  builder.Connect(a->get_output_port(), pass->get_input_port());
  builder.Connect(pass->get_output_port(), a->get_input_port());
  builder.ExportInput(b->get_input_port(), "u");
  auto diagram = builder.Build();
  auto context = diagram->CreateDefaultContext();
  // Continuous states are concatenated in the order the systems were added.
  EXPECT_EQ(context->num_continuous_states(), 5);
  EXPECT_EQ(Eigen::VectorXd(context->get_continuous_state_vector()),
            (Eigen::VectorXd(5) << 1.0, 2.0, 3.0, 4.0, 5.0).finished());
  Context& b_context = diagram->GetMutableSubsystemContext(*b, context.get());
  b_context.SetContinuousState(Eigen::Vector3d(6.0, 7.0, 8.0));
  EXPECT_EQ(context->get_continuous_state_vector()[2], 6.0);
  context->get_mutable_continuous_state_vector()[0] = -1.0;
  EXPECT_EQ(diagram->GetSubsystemContext(*a, *context).get_continuous_state_vector()[0], -1.0);

  CAIRN_EXPECT_THROWS_WITH(context->get_discrete_state(0), std::out_of_range,
                           "diagram 'diagram' holds no discrete state", "GetSubsystemContext");
  CAIRN_EXPECT_THROWS_WITH(b_context.SetTime(1.0), std::logic_error, "subcontext", "root");
  CAIRN_EXPECT_THROWS_WITH(b_context.Clone(), std::logic_error, "clone the root");
  context->SetTime(3.0);
  EXPECT_EQ(b_context.get_time(), 3.0);

  // A clone keeps its own contiguous storage.
  auto clone = context->Clone();
  diagram->GetMutableSubsystemContext(*a, clone.get()).SetContinuousState(Eigen::Vector2d(9.0, 9.0));
  EXPECT_EQ(clone->get_continuous_state_vector()[0], 9.0);
  EXPECT_EQ(context->get_continuous_state_vector()[0], -1.0);
}

}  // namespace
}  // namespace cairn::systems
