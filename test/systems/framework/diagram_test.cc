#include "cairn/systems/framework/diagram.h"

#include <memory>
#include <string>

#include <gtest/gtest.h>

#include "cairn/systems/framework/diagram_builder.h"
#include "cairn/systems/primitives/constant_vector_source.h"
#include "cairn/systems/primitives/gain.h"
#include "cairn/systems/primitives/integrator.h"
#include "cairn/systems/primitives/pass_through.h"
#include "cairn/systems/primitives/zero_order_hold.h"
#include "expect_throws.h"

namespace cairn::systems {
namespace {

// inner: u -> gain(k) -> pass -> y, with an integrator of the input alongside.
std::unique_ptr<Diagram> MakeInner(double k, const std::string& name) {
  DiagramBuilder builder;
  auto* gain = builder.AddNamedSystem<Gain>("gain", k, 2);
  auto* pass = builder.AddNamedSystem<PassThrough>("pass", 2);
  auto* integrator = builder.AddNamedSystem<Integrator>("integrator", Eigen::Vector2d(1.0, 1.0));
  builder.ExportInput(gain->get_input_port(), "u");
  builder.ConnectInput("u", integrator->get_input_port());
  builder.Connect(*gain, *pass);
  builder.ExportOutput(pass->get_output_port(), "y");
  builder.ExportOutput(integrator->get_output_port(), "integral");
  auto diagram = builder.Build();
  diagram->set_name(name);
  return diagram;
}

TEST(DiagramTest, NestedDiagramsEvaluateAndCacheAcrossLevels) {
  DiagramBuilder builder;
  auto* source = builder.AddNamedSystem<ConstantVectorSource>("source", Eigen::Vector2d(1.0, 2.0));
  auto* first = builder.AddSystem(MakeInner(2.0, "first"));
  auto* second = builder.AddSystem(MakeInner(10.0, "second"));
  builder.Connect(source->get_output_port(), first->GetInputPort("u"));
  builder.Connect(first->GetOutputPort("y"), second->GetInputPort("u"));
  builder.ExportOutput(second->GetOutputPort("y"), "y");
  builder.ExportOutput(first->GetOutputPort("integral"), "integral");
  auto diagram = builder.Build();
  EXPECT_EQ(diagram->num_continuous_states(), 4);
  EXPECT_EQ(second->GetSubsystemByName("pass").GetPathName(), "diagram::second::pass");

  auto context = diagram->CreateDefaultContext();
  EXPECT_EQ(diagram->GetOutputPort("y").Eval<Eigen::VectorXd>(*context), Eigen::Vector2d(20.0, 40.0));

  const auto& inner_gain = static_cast<const LeafSystem&>(second->GetSubsystemByName("gain"));
  const Context& gain_context = diagram->GetSubsystemContext(inner_gain, *context);
  const auto gain_ticket = inner_gain.output_port_ticket(0);
  diagram->GetOutputPort("y").Eval<Eigen::VectorXd>(*context);
  EXPECT_EQ(gain_context.num_calculations(gain_ticket), 1);

  // A change upstream (a parameter of the source) reaches the inner gain of the second diagram.
  source->SetValue(&diagram->GetMutableSubsystemContext(*source, context.get()), Eigen::Vector2d(0.0, 1.0));
  EXPECT_EQ(diagram->GetOutputPort("y").Eval<Eigen::VectorXd>(*context), Eigen::Vector2d(0.0, 20.0));
  EXPECT_EQ(gain_context.num_calculations(gain_ticket), 2);

  // Time is not a prerequisite of any output here.
  context->SetTime(5.0);
  diagram->GetOutputPort("y").Eval<Eigen::VectorXd>(*context);
  EXPECT_EQ(gain_context.num_calculations(gain_ticket), 2);

  // Derivatives are gathered from the nested integrators: first integrates the source, second first's output.
  Eigen::VectorXd derivatives;
  diagram->CalcTimeDerivatives(*context, &derivatives);
  EXPECT_EQ(derivatives, (Eigen::VectorXd(4) << 0.0, 1.0, 0.0, 2.0).finished());
}

TEST(DiagramTest, FeedthroughIsComputedThroughSubsystems) {
  auto inner = MakeInner(1.0, "inner");
  EXPECT_TRUE(inner->HasDirectFeedthrough(0, 0));   // u -> gain -> pass -> y
  EXPECT_FALSE(inner->HasDirectFeedthrough(0, 1));  // u -> integrator -> integral: no feedthrough.
  DiagramBuilder builder;
  auto* hold_inner = builder.AddSystem(std::move(inner));
  auto* hold = builder.AddNamedSystem<ZeroOrderHold>("hold", 0.1, 2);
  // Feedback through the integral output needs no hold; through y it would be a loop.
  builder.Connect(hold_inner->GetOutputPort("integral"), hold_inner->GetInputPort("u"));
  builder.Connect(hold_inner->GetOutputPort("y"), hold->get_input_port());
  EXPECT_NO_THROW(builder.Build());
}

TEST(DiagramTest, GetSubsystemContextRejectsForeignSystems) {
  auto diagram = MakeInner(1.0, "inner");
  Gain stranger(1.0, 2);
  stranger.set_name("stranger");
  auto context = diagram->CreateDefaultContext();
  CAIRN_EXPECT_THROWS_WITH(diagram->GetSubsystemContext(stranger, *context), std::invalid_argument,
                           "'stranger' is not a subsystem of diagram 'inner'");
  CAIRN_EXPECT_THROWS_WITH(diagram->GetSubsystemByName("gian"), std::invalid_argument, "did you mean 'gain'");
  CAIRN_EXPECT_THROWS_WITH(diagram->GetMutableSubsystemContext(*diagram, context.get()), std::invalid_argument,
                           "'inner' is not a subsystem of diagram 'inner'");
}

TEST(DiagramTest, GraphvizShowsSubsystemsAndConnections) {
  DiagramBuilder builder;
  auto* source = builder.AddNamedSystem<ConstantVectorSource>("source", Eigen::Vector2d(1.0, 2.0));
  auto* inner = builder.AddSystem(MakeInner(2.0, "inner"));
  builder.Connect(source->get_output_port(), inner->GetInputPort("u"));
  auto diagram = builder.Build();
  const std::string dot = diagram->GetGraphvizString();
  EXPECT_NE(dot.find("digraph"), std::string::npos);
  EXPECT_NE(dot.find("subgraph cluster_s" + std::to_string(inner->id())), std::string::npos);
  EXPECT_NE(dot.find("label=\"inner\""), std::string::npos);
  // The source's output feeds the inner diagram's exported input node.
  EXPECT_NE(dot.find("s" + std::to_string(source->id()) + ":y0 -> s" + std::to_string(inner->id()) + "_u0"),
            std::string::npos);
  EXPECT_NE(dot.find("|gain|"), std::string::npos);
}

}  // namespace
}  // namespace cairn::systems
