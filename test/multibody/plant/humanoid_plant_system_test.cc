// HumanoidPlant as a block: a diagram holding the standing posture as its reference stands; a robot that
// tips over ends the simulation with the fall's reason; bad construction input is refused.

#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include <cairn/multibody/configuration.h>
#include <cairn/multibody/data.h>
#include <cairn/multibody/kinematics.h>
#include <cairn/multibody/plant/humanoid_plant.h>
#include <cairn/systems/analysis/simulator.h>
#include <cairn/systems/framework/diagram_builder.h>
#include <cairn/systems/primitives/constant_vector_source.h>

#include "expect_throws.h"
#include "test_models.h"
#include "test_paths.h"

namespace cairn::multibody {
namespace {

std::string ControlYaml() { return std::string(CAIRN_SOURCE_DIR) + "/data/robots/cairn_humanoid_control.yaml"; }
std::string WalkingYaml() { return std::string(CAIRN_SOURCE_DIR) + "/data/robots/cairn_humanoid_walking.yaml"; }

Eigen::VectorXd StandingQ(const Model& model) {
  Eigen::VectorXd q = NeutralConfiguration(model);
  Data data(model);
  ForwardKinematics(model, data, q);
  q[2] = -data.X_world[static_cast<std::size_t>(model.GetBodyIndex("l_sole"))].translation().z();
  return q;
}

std::vector<TerrainBox> Ground(double friction) {
  TerrainBox ground;
  ground.name = "ground";
  ground.X_WB = Pose(Eigen::Matrix3d::Identity(), Eigen::Vector3d(0.0, 0.0, -0.5));
  ground.size = Eigen::Vector3d(20.0, 20.0, 1.0);
  ground.friction = friction;
  return {ground};
}

TEST(HumanoidPlantSystemTest, StandsInADiagramAndReportsItsMeasurements) {
  const Model model = test::LoadRobot(test::HumanoidUrdf(), true);
  const JointPdController pd = JointPdController::Load(model, ControlYaml());
  HumanoidPlantOptions options;
  options.drives = LoadJointDrives(model, WalkingYaml());
  const Eigen::VectorXd q0 = StandingQ(model);
  systems::DiagramBuilder builder;
  auto* plant = builder.AddNamedSystem<HumanoidPlant>("plant", model, Ground(0.8), pd, q0, options);
  Eigen::VectorXd reference = Eigen::VectorXd::Zero(model.nq() + model.nv());
  reference.head(model.nq()) = q0;
  auto* source = builder.AddNamedSystem<systems::ConstantVectorSource>("reference", reference);
  builder.Connect(source->get_output_port(0), plant->GetInputPort("reference"));
  builder.ExportOutput(plant->GetOutputPort("state"), "state");
  auto diagram = builder.Build();
  systems::Simulator simulator(*diagram);
  const systems::SimulatorStatus status = simulator.AdvanceTo(1.0);
  EXPECT_TRUE(status.reached_boundary_time()) << status.message;
  const systems::Context& context = diagram->GetSubsystemContext(*plant, simulator.get_context());
  const Eigen::VectorXd& x = plant->GetOutputPort("state").Eval<Eigen::VectorXd>(context);
  EXPECT_NEAR(x[2], q0[2], 1e-3);
  const auto& soles = plant->GetOutputPort("contacts").Eval<std::vector<SoleState>>(context);
  ASSERT_EQ(soles.size(), 2u);
  EXPECT_TRUE(soles[0].loaded && soles[1].loaded);
  EXPECT_NEAR(soles[0].normal_force + soles[1].normal_force, model.total_mass() * 9.81, 0.02 * model.total_mass() * 9.81);
  EXPECT_TRUE(plant->GetOutputPort("slips").Eval<std::vector<SlipEvent>>(context).empty());
  const Eigen::VectorXd& energy = plant->GetOutputPort("energy").Eval<Eigen::VectorXd>(context);
  ASSERT_EQ(energy.size(), 3);
  EXPECT_GT(energy[1], 0.0);
  // Standing still, E_ele is nearly all Joule heat.
  EXPECT_GT(energy[2], 0.0);
  EXPECT_LE(energy[2], energy[1]);
  EXPECT_GT(energy[2], 0.5 * energy[1]);
  EXPECT_LT(std::abs(plant->GetOutputPort("zmp").Eval<Eigen::VectorXd>(context).y()), 0.08);
  // 1000 updates of 1 ms: the state at t = 1 s is the plant's after 1000 steps.
  EXPECT_EQ(simulator.num_unrestricted_updates(), 1000);
}

TEST(HumanoidPlantSystemTest, AFallEndsTheSimulationWithItsReason) {
  const Model model = test::LoadRobot(test::HumanoidUrdf(), true);
  // No joint stiffness: the robot collapses.
  const JointPdController limp(model, Eigen::VectorXd::Zero(model.nv()), Eigen::VectorXd::Constant(model.nv(), 1.0));
  const Eigen::VectorXd q0 = StandingQ(model);
  HumanoidPlant plant(model, Ground(0.8), limp, q0);
  systems::Simulator simulator(plant);
  Eigen::VectorXd reference = Eigen::VectorXd::Zero(model.nq() + model.nv());
  reference.head(model.nq()) = q0;
  plant.get_input_port(0).FixValue(&simulator.get_mutable_context(), reference);
  const systems::SimulatorStatus status = simulator.AdvanceTo(5.0);
  EXPECT_EQ(status.reason, systems::SimulatorStatus::Reason::kReachedTerminationCondition);
  EXPECT_NE(status.message.find("the robot fell at t = "), std::string::npos) << status.message;
  EXPECT_LT(status.time, 5.0);
  RecordProperty("fall", status.message);
}

TEST(HumanoidPlantSystemTest, RejectsBadConstruction) {
  const Model model = test::LoadRobot(test::HumanoidUrdf(), true);
  const JointPdController pd = JointPdController::Load(model, ControlYaml());
  CAIRN_EXPECT_THROWS_WITH(HumanoidPlant(model, Ground(0.8), pd, Eigen::VectorXd::Zero(3)), std::invalid_argument,
                           "initial_q has size 3");
  HumanoidPlantOptions options;
  options.base_body = "torso_link_that_is_not_there";
  CAIRN_EXPECT_THROWS_WITH(HumanoidPlant(model, Ground(0.8), pd, StandingQ(model), options), std::invalid_argument,
                           "torso_link_that_is_not_there");
  const Model fixed = test::LoadRobot(test::HumanoidUrdf(), false);
  CAIRN_EXPECT_THROWS_WITH(HumanoidPlant(fixed, Ground(0.8), pd, NeutralConfiguration(fixed)), std::invalid_argument,
                           "has no floating base");
}

}  // namespace
}  // namespace cairn::multibody
