// The plant's measurement of periodic gaits (thesis 2.3.3): a slow level gait is walked and measured, a longer
// step of the same timing costs more COM work (thesis Fig. 2.3: energy grows with step length), the measurement
// repeats exactly, and gaits no ground holds or options out of range are reported. The pipeline measurement (the
// planning chain without the plant) agrees with the walk on what both see.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>

#include <cairn/multibody/urdf_parser.h>
#include <cairn/planning/walk/plant_gait_sampler.h>

#include "../support/shared_oracle.h"
#include "expect_throws.h"
#include "test_paths.h"

namespace cairn::planning {
namespace {

std::shared_ptr<const multibody::Model> Robot() {
  multibody::UrdfOptions urdf;
  urdf.floating_base = true;
  return std::make_shared<const multibody::Model>(
      multibody::ParseUrdfFile(std::string(CAIRN_SOURCE_DIR) + "/data/robots/cairn_humanoid.urdf", urdf));
}

PlantGaitSampler Sampler(PlantGaitOptions options = PlantGaitOptions()) {
  const auto robot = Robot();
  const auto controller = std::make_shared<const multibody::JointPdController>(multibody::JointPdController::Load(
      *robot, std::string(CAIRN_SOURCE_DIR) + "/data/robots/cairn_humanoid_control.yaml"));
  return PlantGaitSampler(test::SharedWalkingModel(), robot, controller, WalkingObjective::kComWorkPlusHeat,
                          std::move(options));
}

PeriodicGait Gait(double dx, double dz) {
  PeriodicGait gait;
  gait.displacement = {dx, 0.2, dz, 0.0};
  gait.parameters = {0.5, 1.2, 0.7};
  return gait;
}

TEST(PlantGaitSamplerTest, MeasuresASlowLevelGaitAndALongerStepCostsMore) {
  const PlantGaitSampler sampler = Sampler();
  const GaitMeasurement short_steps = sampler.Measure(Gait(0.1, 0.0));
  ASSERT_TRUE(short_steps.simulated) << short_steps.reason;
  EXPECT_TRUE(short_steps.feasible) << short_steps.reason;
  EXPECT_EQ(short_steps.reason, "");
  EXPECT_EQ(short_steps.measured_steps, 2);
  EXPECT_EQ(short_steps.gait.num_steps, 6);
  // 6 steps and the closing one of 1.7 s (the stabiliser's reference adds a last double support), then 1 s of
  // standing.
  EXPECT_GE(short_steps.duration, 7 * 1.7 + 1.0);
  EXPECT_LT(short_steps.duration, 7 * 1.7 + 2.0);
  EXPECT_GT(short_steps.com_work, 0.0);
  EXPECT_GT(short_steps.electrical_energy, short_steps.com_work);
  EXPECT_GT(short_steps.heat, 0.0);
  EXPECT_LT(short_steps.heat, short_steps.electrical_energy);
  EXPECT_GT(short_steps.rcof, 0.0);
  EXPECT_LE(short_steps.rcof, 1.0 + 1e-9);
  EXPECT_LE(short_steps.final_error, 0.05);
  EXPECT_GT(short_steps.com_height, 0.6);
  EXPECT_LT(short_steps.com_height, 0.85);
  EXPECT_TRUE(short_steps.predicted.feasible);

  const GaitMeasurement longer = sampler.Measure(Gait(0.2, 0.0));
  ASSERT_TRUE(longer.simulated) << longer.reason;
  EXPECT_GT(longer.com_work, short_steps.com_work);
  EXPECT_GT(longer.predicted.com_work, short_steps.predicted.com_work);

  // The plant, the solvers and the ordering are deterministic.
  const GaitMeasurement again = sampler.Measure(Gait(0.1, 0.0));
  EXPECT_EQ(again.com_work, short_steps.com_work);
  EXPECT_EQ(again.electrical_energy, short_steps.electrical_energy);
  EXPECT_EQ(again.rcof, short_steps.rcof);
  EXPECT_EQ(again.final_error, short_steps.final_error);

  // The pipeline source's measurement settles the same chain without walking: the same whole-body trajectory and
  // reference, so the same torque cost and ZMP margin, and none of the plant's quantities.
  const GaitMeasurement planned = sampler.MeasurePlanned(Gait(0.1, 0.0));
  EXPECT_FALSE(planned.simulated);
  EXPECT_TRUE(planned.feasible) << planned.reason;
  EXPECT_EQ(planned.measured_steps, 2);
  EXPECT_GT(short_steps.torque_cost, 0.0);
  EXPECT_EQ(planned.torque_cost, short_steps.torque_cost);
  EXPECT_EQ(planned.support_margin, short_steps.support_margin);
  EXPECT_GT(planned.support_margin, 0.0);
  EXPECT_TRUE(std::isnan(planned.heat) && std::isnan(planned.electrical_energy) && std::isnan(planned.final_error));
  // The reference's COM is the one the plant followed: its height within 5 cm of the walk's, its RCOF a friction
  // coefficient a level walk needs (between the analytic model's and the plant's, both well under 1).
  EXPECT_NEAR(planned.com_height, short_steps.com_height, 0.05);
  EXPECT_GT(planned.rcof, 0.0);
  EXPECT_LT(planned.rcof, 0.5);
  EXPECT_GT(planned.com_work, 0.0);
  EXPECT_GE(planned.duration, 7 * 1.7) << "the reference's length: the 6 steps and the closing one";
  EXPECT_LT(planned.duration, short_steps.duration) << "no standing after it";
}

TEST(PlantGaitSamplerTest, ThePipelineMeasurementTellsAGaitOutsideTheZmpMarginAndOneWithoutGround) {
  PlantGaitOptions options;
  options.min_support_margin = 0.1;  // more than half a foot's width: no stabilised ZMP stays that far inside
  const GaitMeasurement m = Sampler(options).MeasurePlanned(Gait(0.1, 0.0));
  EXPECT_FALSE(m.feasible);
  EXPECT_GT(m.torque_cost, 0.0) << "measured, only not feasible";
  EXPECT_NE(m.reason.find("least margin inside its support polygon is"), std::string::npos) << m.reason;
  EXPECT_NE(m.reason.find("below the 0.1 m allowed"), std::string::npos) << m.reason;

  const GaitMeasurement none = Sampler().MeasurePlanned(Gait(0.15, 0.1));
  EXPECT_FALSE(none.feasible);
  EXPECT_NE(none.reason.find("no ground for this gait"), std::string::npos) << none.reason;
  EXPECT_TRUE(std::isnan(none.torque_cost));
}

TEST(PlantGaitSamplerTest, AStaircaseNoGroundHoldsIsAResultNotAnError) {
  const GaitMeasurement m = Sampler().Measure(Gait(0.15, 0.1));
  EXPECT_FALSE(m.simulated);
  EXPECT_FALSE(m.feasible);
  EXPECT_NE(m.reason.find("no ground for this gait"), std::string::npos) << m.reason;
  EXPECT_TRUE(std::isnan(m.com_work));
  EXPECT_EQ(m.measured_steps, 0);
}

TEST(PlantGaitSamplerTest, TheSetupWalksTheFixedPlanOnItsGround) {
  const PlantGaitSampler sampler = Sampler();
  const WalkSetup setup = sampler.Setup(Gait(0.3, 0.1));
  ASSERT_NE(setup.plan, nullptr);
  EXPECT_EQ(setup.plan->steps.size(), 7u);
  EXPECT_EQ(setup.plant_terrain.size(), 9u);
  EXPECT_TRUE(std::isnan(setup.trajectory.ground_height));
  EXPECT_TRUE(setup.plant.stop_on_fall);
  EXPECT_FALSE(setup.plant.drives.empty());
  const WalkDiagram walk = BuildWalkDiagram(setup);
  EXPECT_EQ(walk.footsteps, nullptr);
  ASSERT_NE(walk.plan, nullptr);
  EXPECT_EQ(walk.plan->get_system().get_name(), "footsteps");
}

TEST(PlantGaitSamplerTest, RejectsOptionsOutOfRange) {
  PlantGaitOptions options;
  options.num_steps = 4;
  CAIRN_EXPECT_THROWS_WITH(Sampler(options), std::invalid_argument, "num_steps 4", "[5, 100]");
  options = PlantGaitOptions();
  options.ground_friction = 0.0;
  CAIRN_EXPECT_THROWS_WITH(Sampler(options), std::invalid_argument, "ground_friction 0");
  options = PlantGaitOptions();
  options.tracking_tolerance = 2.0;
  CAIRN_EXPECT_THROWS_WITH(Sampler(options), std::invalid_argument, "tracking_tolerance 2 m");
  options = PlantGaitOptions();
  options.min_support_margin = -0.5;
  CAIRN_EXPECT_THROWS_WITH(Sampler(options), std::invalid_argument, "min_support_margin -0.5 m", "[-0.1, 0.1]");
  CAIRN_EXPECT_THROWS_WITH(Sampler().Measure(Gait(0.5, 0.0)), std::invalid_argument, "dx 0.5 m");
}

}  // namespace
}  // namespace cairn::planning
