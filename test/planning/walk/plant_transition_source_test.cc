// The plant and pipeline sources of transition oracles (issue 21): an entry is the cheapest measured gait within
// the friction limit, the settings that shape the measurements are in the oracle's header, and one-cell tables
// hold what the plant measured and what the planning chain produced.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>

#include <cairn/common/number_text.h>
#include <cairn/multibody/urdf_parser.h>
#include <cairn/planning/locomotion/transition_oracle.h>
#include <cairn/planning/walk/plant_transition_source.h>

#include "../support/shared_oracle.h"
#include "expect_throws.h"
#include "test_paths.h"

namespace cairn::planning {
namespace {

std::shared_ptr<const PlantGaitSampler> Sampler() {
  multibody::UrdfOptions urdf;
  urdf.floating_base = true;
  const auto robot = std::make_shared<const multibody::Model>(
      multibody::ParseUrdfFile(std::string(CAIRN_SOURCE_DIR) + "/data/robots/cairn_humanoid.urdf", urdf));
  const auto controller = std::make_shared<const multibody::JointPdController>(multibody::JointPdController::Load(
      *robot, std::string(CAIRN_SOURCE_DIR) + "/data/robots/cairn_humanoid_control.yaml"));
  return std::make_shared<const PlantGaitSampler>(test::SharedWalkingModel(), robot, controller,
                                                  WalkingObjective::kComWorkPlusHeat);
}

// One displacement (0.1 m forward, the feet 0.2 m apart) at a friction limit no walk meets and at 1.
OracleGrid OneCellGrid() {
  OracleGrid grid;
  grid.dx = {0.1};
  grid.dy = {0.2};
  grid.dz = {0.0};
  grid.dtheta = {0.0};
  grid.mu = {0.01, 1.0};
  return grid;
}

GaitMeasurement Measured(double t_ds, double t_sw, bool feasible, double com_work, double heat, double rcof) {
  GaitMeasurement m;
  m.gait.parameters = {t_ds, t_sw, 0.7};
  m.simulated = true;
  m.feasible = feasible;
  m.com_work = com_work;
  m.heat = heat;
  m.rcof = rcof;
  m.com_height = 0.72;
  return m;
}

TEST(PlantTransitionSourceTest, AnEntryIsTheCheapestFeasibleGaitWithinTheFrictionLimit) {
  const std::vector<GaitMeasurement> cell = {
      Measured(0.2, 0.9, true, 5.0, 100.0, 0.30),   // cheapest, but needs mu 0.3
      Measured(0.5, 0.9, true, 6.0, 120.0, 0.15),
      Measured(0.9, 1.2, true, 9.0, 150.0, 0.08),
      Measured(0.2, 1.2, false, 1.0, 10.0, 0.01),   // fell: never an entry
  };
  const std::vector<double> mu = {0.05, 0.1, 0.2, 1.0};
  const std::vector<TransitionCost> heat = PlantTransitionSource::EntriesFrom(cell, WalkingObjective::kComWorkPlusHeat, mu);
  ASSERT_EQ(heat.size(), 4u);
  EXPECT_FALSE(heat[0].feasible);
  ASSERT_TRUE(heat[1].feasible);
  EXPECT_DOUBLE_EQ(heat[1].cost, 159.0);
  EXPECT_DOUBLE_EQ(heat[1].parameters.t_ds, 0.9);
  EXPECT_DOUBLE_EQ(heat[1].parameters.com_height, 0.72) << "the height the walk used";
  EXPECT_DOUBLE_EQ(heat[1].duration, 2.1);
  EXPECT_DOUBLE_EQ(heat[2].cost, 126.0);
  EXPECT_DOUBLE_EQ(heat[2].rcof, 0.15);
  EXPECT_DOUBLE_EQ(heat[3].cost, 105.0);
  EXPECT_DOUBLE_EQ(heat[3].com_work, 5.0);
  EXPECT_DOUBLE_EQ(heat[3].heat, 100.0);

  const std::vector<TransitionCost> work = PlantTransitionSource::EntriesFrom(cell, WalkingObjective::kComWork, mu);
  EXPECT_DOUBLE_EQ(work[3].cost, 5.0);
  const std::vector<TransitionCost> time = PlantTransitionSource::EntriesFrom(cell, WalkingObjective::kTravelTime, mu);
  EXPECT_DOUBLE_EQ(time[3].cost, 1.1);
  EXPECT_DOUBLE_EQ(time[1].cost, 2.1);
  CAIRN_EXPECT_THROWS_WITH(PlantTransitionSource::EntriesFrom(cell, WalkingObjective::kSquaredTorque, mu),
                           std::invalid_argument, "objective 'torque'", "use ecom, ecom_heat or time",
                           "or the pipeline source");
}

TEST(PlantTransitionSourceTest, ThePipelinePricesTheWholeBodyTorquesAndMeasuresNoHeat) {
  std::vector<GaitMeasurement> cell = {
      Measured(0.2, 0.9, true, 5.0, std::nan(""), 0.30),
      Measured(0.5, 0.9, true, 6.0, std::nan(""), 0.15),
  };
  cell[0].torque_cost = 0.4;
  cell[1].torque_cost = 0.3;
  const std::vector<double> mu = {0.2, 1.0};
  const PlantTransitionSource::Mode pipeline = PlantTransitionSource::Mode::kPipeline;
  const std::vector<TransitionCost> torque =
      PlantTransitionSource::EntriesFrom(cell, WalkingObjective::kSquaredTorque, mu, pipeline);
  ASSERT_TRUE(torque[0].feasible && torque[1].feasible);
  EXPECT_DOUBLE_EQ(torque[0].cost, 0.3);
  EXPECT_DOUBLE_EQ(torque[1].cost, 0.3) << "the cheaper torque wins at any limit it satisfies";
  EXPECT_DOUBLE_EQ(torque[1].parameters.t_ds, 0.5);
  EXPECT_EQ(torque[1].heat, 0.0) << "no motor ran";
  const std::vector<TransitionCost> work =
      PlantTransitionSource::EntriesFrom(cell, WalkingObjective::kComWork, mu, pipeline);
  EXPECT_DOUBLE_EQ(work[1].cost, 5.0);
  CAIRN_EXPECT_THROWS_WITH(
      PlantTransitionSource::EntriesFrom(cell, WalkingObjective::kComWorkPlusHeat, mu, pipeline),
      std::invalid_argument, "measures no heat (objective 'ecom_heat')", "use torque, ecom or time");
}

TEST(PlantTransitionSourceTest, ChecksItsTimingsAndDescribesItsSettings) {
  const auto sampler = Sampler();
  const WalkingModel& model = sampler->walking_model();
  CAIRN_EXPECT_THROWS_WITH(PlantTransitionSource(nullptr, {0.5}, {1.2}), std::invalid_argument, "sampler is null");
  CAIRN_EXPECT_THROWS_WITH(PlantTransitionSource(sampler, {}, {1.2}), std::invalid_argument, "t_ds has 0 values");
  CAIRN_EXPECT_THROWS_WITH(PlantTransitionSource(sampler, {0.5, 0.5}, {1.2}), std::invalid_argument,
                           "not strictly increasing at 0.5");
  CAIRN_EXPECT_THROWS_WITH(PlantTransitionSource(sampler, {0.5}, {99.0}), std::invalid_argument, "t_sw value 99 s",
                           "outside the walking model's bounds");

  const PlantTransitionSource source(sampler, PlantTransitionSource::DefaultDoubleSupportTimes(model),
                                     PlantTransitionSource::DefaultSwingTimes(model));
  EXPECT_FALSE(source.concurrent());
  EXPECT_EQ(source.name(), "plant");
  const std::string line = source.Describe();
  // Timings are written exactly (FormatExact), so the line names the very values the entries were measured at.
  const std::string timings = "plant t_ds " + FormatExact(0.2) + ",0.5," + FormatExact(0.9) + " t_sw " +
                              FormatExact(0.9) + ",1.2 steps 6 transient 2 friction 1 ";
  EXPECT_EQ(line.rfind(timings, 0), 0u) << line;
  EXPECT_NE(line.find("stabilizer fft feedback on"), std::string::npos) << line;

  const OracleGrid grid = PlantTransitionSource::DefaultGrid(model);
  EXPECT_NO_THROW(grid.Validate(model.reach()));
  EXPECT_EQ(grid.num_displacements(), 4u * 2u * 1u * 2u);
  CAIRN_EXPECT_THROWS_WITH(
      source.CellEntries(model, WalkingObjective::kSquaredTorque, StepDisplacement{0.1, 0.2, 0.0, 0.0}, {1.0}),
      std::invalid_argument, "no squared static torques");

  // The pipeline's line differs in its name and its feasibility setting (no plant, so no feedback), so neither
  // table is ever read for the other.
  const PlantTransitionSource pipeline(sampler, {0.5}, {1.2}, PlantTransitionSource::Mode::kPipeline);
  EXPECT_EQ(pipeline.name(), "pipeline");
  EXPECT_EQ(pipeline.Describe().rfind("pipeline t_ds 0.5 t_sw 1.2 steps 6 ", 0), 0u) << pipeline.Describe();
  EXPECT_NE(pipeline.Describe().find("stabilizer fft margin 0"), std::string::npos) << pipeline.Describe();
  CAIRN_EXPECT_THROWS_WITH(
      pipeline.CellEntries(model, WalkingObjective::kComWorkPlusHeat, StepDisplacement{0.1, 0.2, 0.0, 0.0}, {1.0}),
      std::invalid_argument, "measures no heat");
}

// One cell at one timing, walked in the plant: the table holds the measured gait where its RCOF is within the limit
// and nothing below it.
TEST(PlantTransitionSourceTest, AOneCellTableHoldsTheMeasuredGait) {
  const auto sampler = Sampler();
  const WalkingModel& model = sampler->walking_model();
  const OracleGrid grid = OneCellGrid();
  OracleBuildOptions options;
  options.source = std::make_shared<const PlantTransitionSource>(sampler, std::vector<double>{0.5},
                                                                 std::vector<double>{1.2});
  const TransitionOracle oracle = TransitionOracle::Build(model, WalkingObjective::kComWorkPlusHeat, grid, options);
  EXPECT_EQ(oracle.source().rfind("plant t_ds 0.5 t_sw 1.2 ", 0), 0u) << oracle.source();
  EXPECT_FALSE(oracle.entry(0, 0, 0, 0, 0).feasible) << "no walk keeps its net RCOF under 0.01";
  const TransitionCost& e = oracle.entry(0, 0, 0, 0, 1);
  ASSERT_TRUE(e.feasible);
  EXPECT_GT(e.com_work, 0.0);
  EXPECT_GT(e.heat, e.com_work);
  EXPECT_DOUBLE_EQ(e.cost, e.com_work + e.heat);
  EXPECT_GT(e.rcof, 0.01);
  EXPECT_LE(e.rcof, 1.0);
  EXPECT_DOUBLE_EQ(e.duration, 1.7);
  EXPECT_GT(e.parameters.com_height, 0.6);
}

// The pipeline's one-cell table: the whole-body torque cost of the gait the chain planned, at every limit its
// reference's RCOF satisfies.
TEST(PlantTransitionSourceTest, AOneCellPipelineTableHoldsThePlannedGaitsTorqueCost) {
  const auto sampler = Sampler();
  const WalkingModel& model = sampler->walking_model();
  const OracleGrid grid = OneCellGrid();
  OracleBuildOptions options;
  options.source = std::make_shared<const PlantTransitionSource>(
      sampler, std::vector<double>{0.5}, std::vector<double>{1.2}, PlantTransitionSource::Mode::kPipeline);
  const TransitionOracle oracle = TransitionOracle::Build(model, WalkingObjective::kSquaredTorque, grid, options);
  EXPECT_EQ(oracle.source().rfind("pipeline t_ds 0.5 t_sw 1.2 ", 0), 0u) << oracle.source();
  EXPECT_FALSE(oracle.entry(0, 0, 0, 0, 0).feasible) << "no reference keeps its RCOF under 0.01";
  const TransitionCost& e = oracle.entry(0, 0, 0, 0, 1);
  ASSERT_TRUE(e.feasible);
  // The source plans its gaits at the middle of the model's COM heights (the optimiser chooses the posture).
  const double height = 0.5 * (model.parameter_lower().com_height + model.parameter_upper().com_height);
  const GaitMeasurement m = sampler->MeasurePlanned(
      PeriodicGait{StepDisplacement{0.1, 0.2, 0.0, 0.0}, StepParameters{0.5, 1.2, height}});
  EXPECT_DOUBLE_EQ(e.cost, m.torque_cost);
  EXPECT_DOUBLE_EQ(e.rcof, m.rcof);
  EXPECT_EQ(e.heat, 0.0);
  EXPECT_DOUBLE_EQ(e.duration, 1.7);
}

}  // namespace
}  // namespace cairn::planning
