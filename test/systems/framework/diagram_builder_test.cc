#include "cairn/systems/framework/diagram_builder.h"

#include <memory>
#include <string>

#include <gtest/gtest.h>

#include "cairn/systems/primitives/adder.h"
#include "cairn/systems/primitives/constant_value_source.h"
#include "cairn/systems/primitives/constant_vector_source.h"
#include "cairn/systems/primitives/gain.h"
#include "cairn/systems/primitives/integrator.h"
#include "cairn/systems/primitives/pass_through.h"
#include "cairn/systems/primitives/zero_order_hold.h"
#include "expect_throws.h"

namespace cairn::systems {
namespace {

TEST(DiagramBuilderTest, ConnectsAndExportsPorts) {
  DiagramBuilder builder;
  auto* source = builder.AddSystem<ConstantVectorSource>(Eigen::Vector3d(1.0, 2.0, 3.0));
  auto* gain = builder.AddNamedSystem<Gain>("gain", 2.0, 3);
  auto* adder = builder.AddNamedSystem<Adder>("adder", 2, 3);
  builder.Connect(*source, *gain);
  builder.Connect(gain->get_output_port(), adder->get_input_port(0));
  builder.ExportInput(adder->get_input_port(1), "offset");
  builder.ExportOutput(adder->get_output_port(), "y");
  EXPECT_EQ(source->get_name(), "constant_vector_source_0");
  auto diagram = builder.Build();
  auto context = diagram->CreateDefaultContext();
  diagram->GetInputPort("offset").FixValue(context.get(), Eigen::Vector3d(0.5, 0.5, 0.5));
  EXPECT_EQ(diagram->GetOutputPort("y").Eval<Eigen::VectorXd>(*context), Eigen::Vector3d(2.5, 4.5, 6.5));
  EXPECT_TRUE(diagram->HasDirectFeedthrough(0, 0));
}

TEST(DiagramBuilderTest, RejectsMismatchedPortsWithBothNamesAndTypes) {
  DiagramBuilder builder;
  auto* three = builder.AddNamedSystem<ConstantVectorSource>("three", Eigen::Vector3d::Zero());
  auto* gain2 = builder.AddNamedSystem<Gain>("gain2", 1.0, 2);
  auto* text = builder.AddNamedSystem<ConstantValueSource<std::string>>("text", std::string("hi"));
  auto* number_pass = builder.AddNamedSystem<PassThrough>("numbers", Value<int>(0));
  CAIRN_EXPECT_THROWS_WITH(builder.Connect(three->get_output_port(), gain2->get_input_port()), std::logic_error,
                           "output port 'y0' of system 'three' (vector of size 3)",
                           "input port 'u' of system 'gain2' (vector of size 2)");
  CAIRN_EXPECT_THROWS_WITH(builder.Connect(text->get_output_port(), gain2->get_input_port()), std::logic_error,
                           "abstract value of type std::string", "vector of size 2");
  CAIRN_EXPECT_THROWS_WITH(builder.Connect(text->get_output_port(), number_pass->get_input_port()), std::logic_error,
                           "abstract value of type std::string", "abstract value of type int");
}

TEST(DiagramBuilderTest, RejectsAnInputConnectedTwice) {
  DiagramBuilder builder;
  auto* a = builder.AddNamedSystem<ConstantVectorSource>("a", Eigen::Vector2d::Zero());
  auto* b = builder.AddNamedSystem<ConstantVectorSource>("b", Eigen::Vector2d::Zero());
  auto* gain = builder.AddNamedSystem<Gain>("gain", 1.0, 2);
  builder.Connect(*a, *gain);
  CAIRN_EXPECT_THROWS_WITH(builder.Connect(*b, *gain), std::logic_error,
                           "input port 'u' of system 'gain' is already connected to the output port 'y0' of system "
                           "'a'",
                           "Adder");
  CAIRN_EXPECT_THROWS_WITH(builder.ExportInput(gain->get_input_port()), std::logic_error, "already connected");
}

TEST(DiagramBuilderTest, BuildListsEveryUnconnectedInput) {
  DiagramBuilder builder;
  builder.AddNamedSystem<Gain>("gain", 1.0, 2);
  builder.AddNamedSystem<Adder>("adder", 2, 2);
  CAIRN_EXPECT_THROWS_WITH(builder.Build(), std::logic_error, "'gain.u', 'adder.u0', 'adder.u1'", "ExportInput",
                           "FixInput");
}

TEST(DiagramBuilderTest, FixedInputsNeedNoSource) {
  DiagramBuilder builder;
  auto* gain = builder.AddNamedSystem<Gain>("gain", 3.0, 1);
  builder.FixInput(gain->get_input_port(), Eigen::VectorXd::Constant(1, 2.0));
  builder.ExportOutput(gain->get_output_port());
  auto diagram = builder.Build();
  auto context = diagram->CreateDefaultContext();
  EXPECT_EQ(diagram->get_output_port().Eval<Eigen::VectorXd>(*context)[0], 6.0);
  EXPECT_EQ(diagram->get_output_port().get_name(), "gain_y");
  // The fixed value can be changed per context.
  Context& gain_context = diagram->GetMutableSubsystemContext(*gain, context.get());
  gain->get_input_port().FixValue(&gain_context, Eigen::VectorXd::Constant(1, 1.0));
  EXPECT_EQ(diagram->get_output_port().Eval<Eigen::VectorXd>(*context)[0], 3.0);
}

TEST(DiagramBuilderTest, RejectsAlgebraicLoopsAndPrintsTheLoop) {
  DiagramBuilder builder;
  auto* a = builder.AddNamedSystem<Gain>("a", 0.5, 1);
  auto* b = builder.AddNamedSystem<Gain>("b", 0.5, 1);
  builder.Connect(*a, *b);
  builder.Connect(*b, *a);
  CAIRN_EXPECT_THROWS_WITH(builder.Build(), std::logic_error, "algebraic loop: a.y -> b.u -> b.y -> a.u -> a.y",
                           "ZeroOrderHold");
}

TEST(DiagramBuilderTest, AZeroOrderHoldOrAnIntegratorBreaksTheLoop) {
  DiagramBuilder builder;
  auto* a = builder.AddNamedSystem<Gain>("a", 0.5, 1);
  auto* hold = builder.AddNamedSystem<ZeroOrderHold>("hold", 0.1, 1);
  builder.Connect(*a, *hold);
  builder.Connect(*hold, *a);
  auto* b = builder.AddNamedSystem<Gain>("b", -1.0, 1);
  auto* integrator = builder.AddNamedSystem<Integrator>("integrator", 1);
  builder.Connect(*b, *integrator);
  builder.Connect(*integrator, *b);
  EXPECT_NO_THROW(builder.Build());
}

TEST(DiagramBuilderTest, RejectsDuplicateNames) {
  DiagramBuilder builder;
  builder.AddNamedSystem<ConstantVectorSource>("same", Eigen::Vector2d::Zero());
  builder.AddNamedSystem<ConstantVectorSource>("same", Eigen::Vector2d::Zero());
  CAIRN_EXPECT_THROWS_WITH(builder.Build(), std::logic_error, "Two systems in the diagram are named 'same'",
                           "unique name");
}

TEST(DiagramBuilderTest, RejectsASystemAddedToTwoBuilders) {
  DiagramBuilder first;
  DiagramBuilder second;
  auto* gain = first.AddNamedSystem<Gain>("gain", 1.0, 1);
  CAIRN_EXPECT_THROWS_WITH(second.AddSystem(std::unique_ptr<Gain>(gain)), std::logic_error,
                           "System 'gain' already belongs to another DiagramBuilder", "separate instance");
  // `first` still owns and can use it.
  first.FixInput(gain->get_input_port(), Eigen::VectorXd::Zero(1));
  EXPECT_NO_THROW(first.Build());
}

TEST(DiagramBuilderTest, RejectsPortsOfSystemsItDoesNotHoldAndUseAfterBuild) {
  DiagramBuilder builder;
  Gain stranger(1.0, 1);
  stranger.set_name("stranger");
  auto* gain = builder.AddNamedSystem<Gain>("gain", 1.0, 1);
  CAIRN_EXPECT_THROWS_WITH(builder.Connect(stranger, *gain), std::logic_error,
                           "system 'stranger' has not been added to this builder", "AddSystem()");
  builder.ExportInput(gain->get_input_port());
  builder.Build();
  CAIRN_EXPECT_THROWS_WITH(builder.Build(), std::logic_error, "after Build()", "new DiagramBuilder");
  CAIRN_EXPECT_THROWS_WITH(builder.AddSystem<Gain>(1.0, 1), std::logic_error, "AddSystem() after Build()");
}

TEST(DiagramBuilderTest, OneDiagramInputCanFeedSeveralSubsystems) {
  DiagramBuilder builder;
  auto* a = builder.AddNamedSystem<Gain>("a", 2.0, 1);
  auto* b = builder.AddNamedSystem<Gain>("b", 3.0, 1);
  auto* sum = builder.AddNamedSystem<Adder>("sum", 2, 1);
  const int u = builder.ExportInput(a->get_input_port(), "u");
  builder.ConnectInput("u", b->get_input_port());
  builder.Connect(a->get_output_port(), sum->get_input_port(0));
  builder.Connect(b->get_output_port(), sum->get_input_port(1));
  builder.ExportOutput(sum->get_output_port(), "y");
  CAIRN_EXPECT_THROWS_WITH(builder.ConnectInput("v", b->get_input_port()), std::invalid_argument,
                           "no exported input named 'v'", "'u'");
  auto diagram = builder.Build();
  auto context = diagram->CreateDefaultContext();
  diagram->get_input_port(u).FixValue(context.get(), Eigen::VectorXd::Constant(1, 1.0));
  EXPECT_EQ(diagram->get_output_port().Eval<Eigen::VectorXd>(*context)[0], 5.0);
  CAIRN_EXPECT_THROWS_WITH(a->get_input_port().FixValue(&diagram->GetMutableSubsystemContext(*a, context.get()),
                                                        Eigen::VectorXd::Zero(1)),
                           std::logic_error, "exported as input 'u' of diagram 'diagram'");
}

}  // namespace
}  // namespace cairn::systems
