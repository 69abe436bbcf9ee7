#include <cmath>

#include <gtest/gtest.h>

#include "cairn/perception/terrain/elevation_mapper.h"
#include "cairn/perception/terrain/map_registration.h"
#include "cairn/perception/terrain/probe_controller.h"
#include "cairn/perception/terrain/traversability_analyzer.h"
#include "cairn/systems/analysis/simulator.h"
#include "expect_throws.h"

namespace cairn::perception {
namespace {

// A flat floor at z = 0.2 with plants on its x > 0 half, 1 m around the origin.
void Floor(Eigen::Matrix3Xd* points, Eigen::MatrixXd* probabilities) {
  const int n = 40;
  points->resize(3, n * n);
  probabilities->resize(2, n * n);
  for (int a = 0; a < n; ++a) {
    for (int b = 0; b < n; ++b) {
      const int k = a * n + b;
      points->col(k) = Eigen::Vector3d(-1.0 + (a + 0.5) * 0.05, -1.0 + (b + 0.5) * 0.05, 0.2);
      (*probabilities)(0, k) = points->col(k).x() > 0.0 ? 0.9 : 0.05;
      (*probabilities)(1, k) = 0.05;
    }
  }
}

TEST(TerrainSystemsTest, MapperAnalyzerAndProbesGiveAlgorithmOne) {
  const GridMap prototype(Eigen::Vector2i(20, 20), 0.1, Eigen::Vector2d::Zero());
  ElevationMapper mapper(prototype, 0.1, ElevationMapper::Options{});
  auto context = mapper.CreateDefaultContext();
  Eigen::Matrix3Xd points;
  Eigen::MatrixXd probabilities;
  Floor(&points, &probabilities);
  mapper.get_points_input_port().FixValue(context.get(), systems::Value<Eigen::Matrix3Xd>(points));
  mapper.get_sensor_input_port().FixValue(context.get(), Eigen::Vector3d(0.0, 0.0, 1.0));
  mapper.get_probabilities_input_port().FixValue(context.get(), systems::Value<Eigen::MatrixXd>(probabilities));
  EXPECT_TRUE(std::isnan(mapper.get_map_output_port().Eval<GridMap>(*context).ValueAt("elevation", Eigen::Vector2d::Zero())));
  systems::Simulator simulator(mapper, std::move(context));
  simulator.AdvanceTo(0.25);  // updates at 0, 0.1, 0.2
  const GridMap& map = mapper.get_map_output_port().Eval<GridMap>(simulator.get_context());
  EXPECT_NEAR(map.ValueAt("elevation", Eigen::Vector2d(-0.5, 0.3)), 0.2, 1e-12);
  EXPECT_NEAR(map.ValueAt("slope", Eigen::Vector2d(-0.5, 0.3)), 0.0, 1e-9);
  EXPECT_NEAR(map.ValueAt("semantic_plants", Eigen::Vector2d(0.5, 0.3)), 0.9, 1e-12);

  TraversabilityAnalyzer analyzer;
  auto ac = analyzer.CreateDefaultContext();
  analyzer.get_map_input_port().FixValue(ac.get(), map);
  std::vector<ProbedRegion> probes{{{Eigen::Vector2d(0.55, 0.55)}, 0.7}};
  analyzer.get_probes_input_port().FixValue(ac.get(), probes);
  const GridMap& analysed = analyzer.get_map_output_port().Eval<GridMap>(*ac);
  EXPECT_DOUBLE_EQ(analysed.ValueAt("traversability", Eigen::Vector2d(-0.5, 0.3)), 1.0);  // flat, no class
  EXPECT_DOUBLE_EQ(analysed.ValueAt("traversability", Eigen::Vector2d(0.5, 0.3)), 0.8);   // plants
  EXPECT_NEAR(analysed.ValueAt("traversability", Eigen::Vector2d(0.55, 0.55)), 0.3, 1e-12);  // probed: 1 - C
  const auto& raster = analyzer.get_traversability_output_port().Eval<Eigen::MatrixXd>(*ac);
  ASSERT_EQ(raster.rows(), 20);
  EXPECT_NEAR(raster(15, 15), 0.3, 1e-12);  // cell (15, 15) holds (0.55, 0.55)
}

// A flat floor at height z over x in [-1.5, 3.5), y in [-1.5, 1.5), every 5 cm.
Eigen::Matrix3Xd WideFloor(double z) {
  Eigen::Matrix3Xd points(3, 100 * 60);
  for (int a = 0; a < 100; ++a) {
    for (int b = 0; b < 60; ++b) {
      points.col(a * 60 + b) = Eigen::Vector3d(-1.5 + (a + 0.5) * 0.05, -1.5 + (b + 0.5) * 0.05, z);
    }
  }
  return points;
}

// A robot-centred map (follow_sensor) moves with the sensor: cells that stay keep their estimate and fuse the new
// frame, cells that leave are forgotten, and a global map keeps what the local one forgot (seed 001 §4.2).
TEST(TerrainSystemsTest, ARobotCentredMapMovesWithTheSensorAndRegistersIntoAGlobalMap) {
  const GridMap prototype(Eigen::Vector2i(20, 20), 0.1, Eigen::Vector2d::Zero());
  ElevationMapper::Options options;
  options.follow_sensor = true;
  ElevationMapper mapper(prototype, 0.1, options);
  TraversabilityAnalyzer analyzer;
  const MapRegistration registration({{"elevation", "elevation", 0.0, "elevation_variance"},
                                      {"traversability", "traversability", 0.0, "traversability_variance"}});
  GridMap global(Eigen::Vector2i(50, 30), 0.1, Eigen::Vector2d(1.0, 0.0));
  registration.AddLayers(&global);

  auto context = mapper.CreateDefaultContext();
  mapper.get_probabilities_input_port().FixValue(context.get(),
                                                 systems::Value<Eigen::MatrixXd>(Eigen::MatrixXd(2, 0)));
  systems::Simulator simulator(mapper, std::move(context));
  auto ac = analyzer.CreateDefaultContext();
  analyzer.get_probes_input_port().FixValue(ac.get(), std::vector<ProbedRegion>());
  // Frame k at time 0.1 k: the sensor at x = sensor_x, the floor at height z.
  const auto frame = [&](int k, double sensor_x, double z) {
    systems::Context& c = simulator.get_mutable_context();
    mapper.get_points_input_port().FixValue(&c, systems::Value<Eigen::Matrix3Xd>(WideFloor(z)));
    mapper.get_sensor_input_port().FixValue(&c, Eigen::Vector3d(sensor_x, 0.0, 1.0));
    simulator.AdvanceTo(0.1 * k + 0.05);
    const GridMap& local = mapper.get_map_output_port().Eval<GridMap>(simulator.get_context());
    analyzer.get_map_input_port().FixValue(ac.get(), local);
    registration.Register(analyzer.get_map_output_port().Eval<GridMap>(*ac), &global);
    return local;
  };
  const Eigen::Vector2d behind(-0.55, 0.05), overlap(0.55, 0.05), ahead(1.55, 0.05);
  GridMap local = frame(0, 0.0, 0.2);
  EXPECT_TRUE(local.center().isApprox(Eigen::Vector2d::Zero()));
  EXPECT_NEAR(local.ValueAt("elevation", behind), 0.2, 1e-12);
  local = frame(1, 1.0, 0.4);
  EXPECT_TRUE(local.center().isApprox(Eigen::Vector2d(1.0, 0.0)));
  const double fused = local.ValueAt("elevation", overlap);
  EXPECT_GT(fused, 0.2 + 1e-3);  // kept across the move and fused with the new frame
  EXPECT_LT(fused, 0.4 - 1e-3);
  EXPECT_NEAR(local.ValueAt("elevation", ahead), 0.4, 1e-12);  // entered with the move: this frame only
  local = frame(2, 0.0, 0.6);
  EXPECT_NEAR(local.ValueAt("elevation", behind), 0.6, 1e-12);  // it left the map at the last move: forgotten
  EXPECT_GT(local.ValueAt("elevation", overlap), fused);

  // The global map kept every frame of every cell it saw, and the flat floor's traversability.
  EXPECT_GT(global.ValueAt("elevation", behind), 0.2 + 1e-3);  // frames 0 and 2
  EXPECT_LT(global.ValueAt("elevation", behind), 0.6 - 1e-3);
  EXPECT_NEAR(global.ValueAt("elevation", ahead), 0.4, 1e-12);  // frame 1 only: frame 2's map ends at x = 1
  // The floor is traversable (the steps between the frames' heights leave some roughness near the map's edges).
  EXPECT_GT(global.ValueAt("traversability", overlap), 0.5);
  EXPECT_TRUE(std::isnan(global.ValueAt("elevation", Eigen::Vector2d(3.45, 0.05))));  // never in a local map
}

// Probes are measurements fused by eq. 1 (seed 001 §4.2), not overwrites: a cell probed at C = 0.7 and then at
// C = 0.3 holds 0.5 with half the probe variance; a probe with several points in one cell counts once there.
TEST(TerrainSystemsTest, TheAnalyzerFusesProbesOfACell) {
  GridMap map(Eigen::Vector2i(4, 4), 0.1, Eigen::Vector2d::Zero());
  map.AddLayer("slope", 0.0);
  map.AddLayer("roughness", 0.0);
  const TraversabilityAnalyzer analyzer;
  GridMap out(Eigen::Vector2i(1, 1), 1.0, Eigen::Vector2d::Zero());
  const Eigen::Vector2d cell(0.05, 0.05), other(-0.05, 0.05);
  analyzer.CalcMap(map, {{{cell, Eigen::Vector2d(0.06, 0.04), other}, 0.7}, {{cell}, 0.3}}, &out);
  const double vp = HierarchicalTraversability().options().probe_variance;
  EXPECT_NEAR(out.ValueAt("collapsibility", cell), 0.5, 1e-12);
  EXPECT_NEAR(out.ValueAt("collapsibility_variance", cell), vp / 2, 1e-15);
  EXPECT_NEAR(out.ValueAt("traversability", cell), 0.5, 1e-12);
  EXPECT_NEAR(out.ValueAt("collapsibility", other), 0.7, 1e-12);
  EXPECT_NEAR(out.ValueAt("collapsibility_variance", other), vp, 1e-15);
  EXPECT_NEAR(out.ValueAt("traversability_variance", cell), vp, 1e-15);  // a probed cell: the probe's variance
  EXPECT_TRUE(std::isnan(out.ValueAt("collapsibility", Eigen::Vector2d(0.15, 0.15))));
}

TEST(TerrainSystemsTest, ProbeControllerAveragesTheProbesForce) {
  ProbeController controller(CollapsibilityEstimator::Options{100.0, 5}, 0.01);
  auto context = controller.CreateDefaultContext();
  controller.get_force_input_port().FixValue(context.get(), Eigen::VectorXd::Constant(1, 40.0));
  controller.get_probing_input_port().FixValue(context.get(), Eigen::VectorXd::Constant(1, 1.0));
  EXPECT_TRUE(std::isnan(controller.get_collapsibility_output_port().Eval<Eigen::VectorXd>(*context)[0]));
  systems::Simulator simulator(controller, std::move(context));
  simulator.AdvanceTo(0.095);  // ten samples, the window keeps five
  const Eigen::VectorXd c = controller.get_collapsibility_output_port().Eval<Eigen::VectorXd>(simulator.get_context());
  EXPECT_DOUBLE_EQ(c[0], 0.6);
  EXPECT_EQ(c[1], 5.0);
  CAIRN_EXPECT_THROWS_WITH(ProbeController(CollapsibilityEstimator::Options{}, 0.0), std::invalid_argument,
                           "period 0 s");
}

// A new probe (the probing input switching on again) starts from an empty window: the last probe's force does not
// leak into the next region's C.
TEST(TerrainSystemsTest, ProbeControllerStartsEachProbeFromAnEmptyWindow) {
  ProbeController controller(CollapsibilityEstimator::Options{100.0, 5}, 0.01);
  auto context = controller.CreateDefaultContext();
  controller.get_force_input_port().FixValue(context.get(), Eigen::VectorXd::Constant(1, 40.0));
  controller.get_probing_input_port().FixValue(context.get(), Eigen::VectorXd::Constant(1, 1.0));
  systems::Simulator simulator(controller, std::move(context));
  simulator.AdvanceTo(0.035);  // four samples of 40 N
  systems::Context& c = simulator.get_mutable_context();
  controller.get_probing_input_port().FixValue(&c, Eigen::VectorXd::Constant(1, 0.0));
  simulator.AdvanceTo(0.065);  // the arm lifts: no samples, the last C is kept
  EXPECT_DOUBLE_EQ(controller.get_collapsibility_output_port().Eval<Eigen::VectorXd>(c)[0], 0.6);
  controller.get_force_input_port().FixValue(&c, Eigen::VectorXd::Constant(1, 90.0));
  controller.get_probing_input_port().FixValue(&c, Eigen::VectorXd::Constant(1, 1.0));
  simulator.AdvanceTo(0.085);  // two samples of 90 N
  const Eigen::VectorXd reading = controller.get_collapsibility_output_port().Eval<Eigen::VectorXd>(c);
  EXPECT_DOUBLE_EQ(reading[0], 0.1);
  EXPECT_EQ(reading[1], 2.0);
}

}  // namespace
}  // namespace cairn::perception
