#include <cmath>

#include <gtest/gtest.h>

#include "cairn/perception/terrain/elevation_mapper.h"
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

}  // namespace
}  // namespace cairn::perception
