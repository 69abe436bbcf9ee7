#include "cairn/perception/occupancy/confidence_to_occupancy.h"

#include <stdexcept>

#include <gtest/gtest.h>

#include "cairn/perception/stereo/compute_confidence.h"
#include "cairn/perception/stereo/compute_cost_volume.h"
#include "cairn/perception/stereo/cost_samples.h"
#include "cairn/perception/stereo/stereo_matcher.h"
#include "cairn/perception/synthetic/bars_scenario.h"
#include "cairn/perception/synthetic/synthetic_stereo_source.h"
#include "cairn/systems/analysis/simulator.h"
#include "cairn/systems/framework/diagram_builder.h"
#include "expect_throws.h"

namespace cairn::perception {
namespace {

const StereoCalibration kCalibration{10.0, 10.0, 1.5, 1.5, 0.5};

OccupancyGrid SmallGrid() { return OccupancyGrid(Eigen::Vector3d(-1.0, -1.0, 0.0), 0.1, Eigen::Vector3i(20, 20, 30)); }

// A 4 x 4 image whose every pixel is sure its surface is at disparity 3 (depth fb / 3 = 1.67 m).
DisparityVolume SureConfidence() {
  DisparityVolume confidence(4, 4, 1, 8);
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 4; ++x)
      for (int k = 0; k < 8; ++k) confidence.mutable_curve(y, x)[k] = k == 2 ? 1.0f : 0.0f;
  return confidence;
}

TEST(ConfidenceToOccupancyTest, IntegratesOneFramePerPeriodFromFixedInputs) {
  ConfidenceToOccupancy system(SmallGrid(), kCalibration, 0.1);
  auto context = system.CreateDefaultContext();
  system.get_confidence_input_port().FixValue(context.get(), SureConfidence());
  system.get_pose_input_port().FixValue(context.get(), Eigen::Isometry3d(Eigen::Isometry3d::Identity()));
  EXPECT_TRUE(system.get_grid_output_port().Eval<OccupancyGrid>(*context).OccupiedCells().empty());
  systems::Simulator simulator(system, std::move(context));
  simulator.AdvanceTo(0.25);  // updates at t = 0, 0.1, 0.2
  OccupancyGrid expected = SmallGrid();
  for (int i = 0; i < 3; ++i) {
    CostCurveSensorModel().Integrate(SureConfidence(), kCalibration, Eigen::Isometry3d::Identity(), &expected);
  }
  const auto& grid = system.get_grid_output_port().Eval<OccupancyGrid>(simulator.get_context());
  ASSERT_FALSE(expected.OccupiedCells().empty());
  EXPECT_EQ(grid.OccupiedCells(), expected.OccupiedCells());
  for (std::size_t i = 0; i < grid.num_cells(); ++i) ASSERT_EQ(grid.log_odds(i), expected.log_odds(i)) << i;
  EXPECT_GT(grid.Probability(Eigen::Vector3d(0.0, 0.0, 5.0 / 3.0)), 0.5);
}

// A diagram that perceives before it plans forces the first frame and starts the periods one period later.
TEST(ConfidenceToOccupancyTest, AForcedUpdateIntegratesNowAndTheOffsetDelaysThePeriodicOnes) {
  ConfidenceToOccupancy system(SmallGrid(), kCalibration, 0.1, {}, 0.1);
  EXPECT_EQ(system.offset(), 0.1);
  auto context = system.CreateDefaultContext();
  system.get_confidence_input_port().FixValue(context.get(), SureConfidence());
  system.get_pose_input_port().FixValue(context.get(), Eigen::Isometry3d(Eigen::Isometry3d::Identity()));
  systems::Simulator simulator(system, std::move(context));
  simulator.Initialize();
  system.ExecuteForcedEvents(&simulator.get_mutable_context());
  OccupancyGrid expected = SmallGrid();
  CostCurveSensorModel().Integrate(SureConfidence(), kCalibration, Eigen::Isometry3d::Identity(), &expected);
  auto grid_now = [&]() -> const OccupancyGrid& {
    return system.get_grid_output_port().Eval<OccupancyGrid>(simulator.get_context());
  };
  for (std::size_t i = 0; i < expected.num_cells(); ++i) ASSERT_EQ(grid_now().log_odds(i), expected.log_odds(i)) << i;
  simulator.AdvanceTo(0.15);  // one periodic update, at t = 0.1 (none at t = 0)
  CostCurveSensorModel().Integrate(SureConfidence(), kCalibration, Eigen::Isometry3d::Identity(), &expected);
  for (std::size_t i = 0; i < expected.num_cells(); ++i) ASSERT_EQ(grid_now().log_odds(i), expected.log_odds(i)) << i;
}

TEST(ConfidenceToOccupancyTest, RejectsBadPeriod) {
  CAIRN_EXPECT_THROWS_WITH(ConfidenceToOccupancy(SmallGrid(), kCalibration, -1.0), std::invalid_argument,
                           "period -1 s", "positive");
  CAIRN_EXPECT_THROWS_WITH(ConfidenceToOccupancy(SmallGrid(), kCalibration, 0.1, {}, -0.5), std::invalid_argument,
                           "offset -0.5 s must be finite and >= 0");
}

// Source -> matcher -> grid, simulated: the same grid as calling the algorithms frame by frame.
TEST(ConfidenceToOccupancyTest, DiagramMatchesTheAlgorithmsFrameByFrame) {
  // The plumbing, not the reconstruction, is under test: a quarter of the scenario's pixels keeps it fast.
  BarsScenario bars = BarsScenario::Make(3);
  bars.width /= 2;
  bars.height /= 2;
  bars.calibration = StereoCalibration{300.0, 300.0, 159.5, 119.5, bars.calibration.baseline};
  bars.min_disparity /= 2;
  bars.max_disparity /= 2;
  SyntheticStereoRenderer renderer(bars.calibration, bars.width, bars.height, 0.0, 1);
  const OccupancyGrid prototype(bars.grid_min_corner, bars.grid_resolution, bars.grid_dims);
  StereoMatcher::Options options;
  options.cost_volume.cost = CostFunction::kBtSad;
  options.cost_volume.window = 9;
  options.cost_volume.min_disparity = bars.min_disparity;
  options.cost_volume.max_disparity = bars.max_disparity;
  systems::DiagramBuilder builder;
  auto* source = builder.AddSystem<SyntheticStereoSource>(bars.scene, renderer, bars.trajectory, 0.1);
  auto* matcher = builder.AddSystem<StereoMatcher>(options);
  auto* fusion = builder.AddSystem<ConfidenceToOccupancy>(prototype, bars.calibration, 0.1);
  builder.Connect(source->get_left_output_port(), matcher->get_left_input_port());
  builder.Connect(source->get_right_output_port(), matcher->get_right_input_port());
  builder.Connect(matcher->get_confidence_output_port(), fusion->get_confidence_input_port());
  builder.Connect(source->get_pose_output_port(), fusion->get_pose_input_port());
  builder.ExportOutput(fusion->get_grid_output_port(), "grid");
  auto diagram = builder.Build();
  systems::Simulator simulator(*diagram);
  simulator.AdvanceTo(0.25);
  const auto& grid = diagram->get_output_port(0).Eval<OccupancyGrid>(simulator.get_context());

  OccupancyGrid expected = prototype;
  for (int f = 0; f < 3; ++f) {
    const auto frame = renderer.Render(bars.scene, bars.trajectory[f], f);
    DisparityVolume costs;
    ComputeCostVolume(frame.left, frame.right, options.cost_volume, &costs);
    WtaResult wta;
    ComputeWinnerTakeAll(costs, options.wta, &wta);
    std::vector<float> samples;
    CollectConsistentWtaCosts(costs, wta, &samples);
    DisparityVolume confidence;
    ComputeConfidence(costs, ConfidenceModel::FitMaximumLikelihood(options.model, options.cost_volume.cost, samples),
                      &confidence);
    CostCurveSensorModel().Integrate(confidence, bars.calibration, frame.X_WC, &expected);
  }
  ASSERT_GT(expected.OccupiedCells().size(), 100u);
  EXPECT_EQ(grid.OccupiedCells(), expected.OccupiedCells());
}

}  // namespace
}  // namespace cairn::perception
