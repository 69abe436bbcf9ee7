// The main diagram (issue 18): the head camera's stereo pair -> geometry and friction -> terrain -> the walk. What
// the perception makes of thesis 5.2.3's mock-up, and what the plan and the plant do with it.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>
#include <memory>
#include <string>

#include <cairn/multibody/urdf_parser.h>
#include <cairn/perception/friction/make_material_segmenter.h>
#include <cairn/planning/run/main_diagram.h>
#include <cairn/planning/run/scenario_stereo_scene.h>
#include <cairn/systems/primitives/constant_vector_source.h>

#include "../support/shared_oracle.h"
#include "expect_throws.h"
#include "test_paths.h"

namespace cairn::planning {
namespace {

FootstepScenario Mockup(const std::string& name) {
  return FootstepScenario::Load(std::string(CAIRN_SOURCE_DIR) + "/examples/scenarios/mockup/" + name);
}

std::shared_ptr<const perception::MaterialSegmenter> Segmenter() {
  static const auto segmenter = perception::MakeMaterialSegmenter(
      "builtin:" + std::string(CAIRN_SOURCE_DIR) + "/data/models/builtin_material_segmenter.yaml");
  return segmenter;
}

// The walk of a scenario with the project's humanoid and the shared test oracle, under an expansion budget.
WalkSetup WalkFor(const FootstepScenario& scenario) {
  multibody::UrdfOptions urdf;
  urdf.floating_base = true;
  const auto robot = std::make_shared<const multibody::Model>(
      multibody::ParseUrdfFile(std::string(CAIRN_SOURCE_DIR) + "/data/robots/cairn_humanoid.urdf", urdf));
  const auto controller = std::make_shared<const multibody::JointPdController>(multibody::JointPdController::Load(
      *robot, std::string(CAIRN_SOURCE_DIR) + "/data/robots/cairn_humanoid_control.yaml"));
  WalkSetup setup = WalkSetupFromScenario(scenario, test::SharedOracle(WalkingObjective::kComWorkPlusHeat),
                                          test::SharedWalkingModel(), WalkingObjective::kComWorkPlusHeat, robot,
                                          controller);
  setup.planner.search.time_limit = 600.0;  // the scenarios' wall-clock limit, as a budget of expansions
  setup.planner.search.max_expansions = 20000;
  return setup;
}

MainDiagram Build(const FootstepScenario& scenario) {
  const SyntheticCamera camera;
  const PerceptionSetup perception = PerceptionSetupFromScenario(scenario, camera.Calibration(), Segmenter());
  return BuildMainDiagram(WalkFor(scenario), perception, ScenarioCamera(scenario, camera, perception.period));
}

// The whole main diagram run on a scenario: perceived, planned and walked, with `settle_time` after the reference.
MainRecord RunWhole(const FootstepScenario& scenario, double settle_time) {
  WalkRunOptions options;
  options.settle_time = settle_time;
  return RunMainDiagram(Build(scenario), options);
}

// The terrain the planner would read after the first frame (perception only: no planning).
TerrainMap Perceive(const MainDiagram& main) {
  const systems::Diagram& diagram = *main.walk.diagram;
  auto root = diagram.CreateDefaultContext();
  main.occupancy->ExecuteForcedEvents(&diagram.GetMutableSubsystemContext(*main.occupancy, root.get()));
  return main.terrain->get_terrain_output_port().Eval<TerrainMap>(diagram.GetSubsystemContext(*main.terrain, *root));
}

// Over the cells of a rectangle: the share with ground, the median height of those, the share of those that are
// walkable and the median friction of the walkable ones.
struct CellSummary {
  double seen{0.0}, height{0.0}, walkable{0.0}, friction{0.0};
};
double Median(std::vector<double> v) {
  if (v.empty()) return std::nan("");
  std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2), v.end());
  return v[v.size() / 2];
}
CellSummary Summarise(const TerrainMap& terrain, double x0, double y0, double x1, double y1) {
  int cells = 0;
  std::vector<double> heights, frictions;
  for (int row = 0; row < terrain.rows(); ++row) {
    for (int col = 0; col < terrain.cols(); ++col) {
      const Eigen::Vector2d c = terrain.CellCenter(col, row);
      if (c.x() < x0 || c.x() > x1 || c.y() < y0 || c.y() > y1) continue;
      ++cells;
      if (!terrain.has_ground(col, row)) continue;
      heights.push_back(terrain.height(col, row));
      if (terrain.walkable(col, row)) frictions.push_back(terrain.friction(col, row));
    }
  }
  CellSummary s;
  s.seen = cells > 0 ? static_cast<double>(heights.size()) / cells : 0.0;
  s.walkable = heights.empty() ? 0.0 : static_cast<double>(frictions.size()) / heights.size();
  s.height = Median(heights);
  s.friction = Median(frictions);
  return s;
}

// Q_{0.05} of a material of the mock-up's registry (materials.yaml: wood 0.10, ceramic 0.40).
double QuantileOf(const FootstepScenario& scenario, const std::string& label) {
  const auto& registry = scenario.registry();
  return registry.material(registry.IndexOf(label)).friction.Quantile(1.0 - scenario.eta());
}

TEST(PerceptionSetupFromScenarioTest, MapsTheScenarioAreaAndTheCamerasDepths) {
  const FootstepScenario scenario = Mockup("mockup_obstacle.yaml");
  const perception::StereoCalibration calibration = SyntheticCamera().Calibration();
  const PerceptionSetup setup = PerceptionSetupFromScenario(scenario, calibration, Segmenter(), 3.0);
  ASSERT_NE(setup.grid, nullptr);
  EXPECT_DOUBLE_EQ(setup.grid->resolution(), 0.025);
  EXPECT_TRUE(setup.grid->min_corner().isApprox(Eigen::Vector3d(-0.6, -0.9, -0.1), 1e-12));
  // The grid reaches 1 m above the highest region, covering the scenario's area.
  EXPECT_GE(setup.grid->resolution() * setup.grid->dims().x(), 2.4 - 1e-9);
  EXPECT_GE(setup.grid->resolution() * setup.grid->dims().y(), 1.8 - 1e-9);
  EXPECT_GE(setup.grid->resolution() * setup.grid->dims().z(), 1.1 - 1e-9);
  // Depths 0.5..3 m are within the matcher's disparities.
  const double fb = calibration.depth_times_disparity();
  EXPECT_LE(setup.matcher.cost_volume.min_disparity, fb / 3.0);
  EXPECT_GE(setup.matcher.cost_volume.max_disparity, fb / 0.5);
  EXPECT_EQ(setup.registry.material(setup.registry.IndexOf("wood")).friction.a(), 0.3);
  EXPECT_EQ(setup.eta, 0.95);
  CAIRN_EXPECT_THROWS_WITH(PerceptionSetupFromScenario(scenario, calibration, nullptr), std::invalid_argument,
                           "the segmenter is null");
  CAIRN_EXPECT_THROWS_WITH(PerceptionSetupFromScenario(scenario, calibration, Segmenter(), 0.2),
                           std::invalid_argument, "max_depth must be in (0.5, 100] m; got 0.2");
}

TEST(BuildMainDiagramTest, NamesWhatIsMissing) {
  const FootstepScenario scenario = Mockup("mockup.yaml");
  const SyntheticCamera camera;
  const PerceptionSetup perception = PerceptionSetupFromScenario(scenario, camera.Calibration(), Segmenter());
  const WalkSetup walk = WalkFor(scenario);
  CAIRN_EXPECT_THROWS_WITH(BuildMainDiagram(walk, perception, nullptr), std::invalid_argument, "the camera is null");
  auto not_a_camera = std::make_unique<systems::ConstantVectorSource>(Eigen::VectorXd::Zero(1));
  not_a_camera->set_name("zeros");
  CAIRN_EXPECT_THROWS_WITH(BuildMainDiagram(walk, perception, std::move(not_a_camera)), std::invalid_argument,
                           "the camera 'zeros' has no output 'left'");
  PerceptionSetup no_segmenter = perception;
  no_segmenter.segmenter = nullptr;
  CAIRN_EXPECT_THROWS_WITH(BuildMainDiagram(walk, no_segmenter, ScenarioCamera(scenario, camera, 1.0)),
                           std::invalid_argument, "PerceptionSetup::segmenter is null");
}

TEST(MainDiagramTest, IsOneDiagramFromTheCameraToThePlant) {
  const MainDiagram main = Build(Mockup("mockup.yaml"));
  const std::string dot = main.walk.diagram->GetGraphvizString();
  for (const char* block : {"camera", "stereo", "depth", "occupancy", "friction", "terrain_assembler", "footsteps",
                            "trajectory", "stabilizer", "plant"}) {
    EXPECT_NE(dot.find(block), std::string::npos) << block;
  }
  EXPECT_EQ(main.walk.diagram->get_name(), "main");
}

// What the head camera's first frame makes of the mock-up (measured 2026-12-05, docs/main_diagram.md): the wood is
// reconstructed everywhere the camera looks, at its height, and all of it is walkable at its friction quantile; the
// ceramic tiles, nearly textureless between their joints, are reconstructed in part (about 73 % once the cells a
// mismatch put centimetres off the floor are dropped), and about 90 % of that is walkable at the ceramic's quantile
// (the points of a cell fused as independent looks at its material). Behind the camera's view nothing is known.
TEST(MainDiagramTest, PerceivesTheMockupsGroundAndFriction) {
  const FootstepScenario scenario = Mockup("mockup.yaml");
  const TerrainMap terrain = Perceive(Build(scenario));
  const CellSummary wood = Summarise(terrain, 0.3, 0.15, 1.1, 0.5);
  const CellSummary tiles = Summarise(terrain, 0.3, -0.5, 1.1, -0.15);
  std::printf("wood: seen %.2f, height %.3f m, walkable %.2f, friction %.3f; tiles: seen %.2f, height %.3f m, "
              "walkable %.2f, friction %.3f\n",
              wood.seen, wood.height, wood.walkable, wood.friction, tiles.seen, tiles.height, tiles.walkable,
              tiles.friction);
  EXPECT_GT(wood.seen, 0.95);
  EXPECT_NEAR(wood.height, 0.001, 0.005);  // the wood's top (1 mm above the tiles, ScenarioStereoScene)
  EXPECT_GT(wood.walkable, 0.95);
  EXPECT_NEAR(wood.friction, QuantileOf(scenario, "wood"), 0.03);
  EXPECT_GT(tiles.seen, 0.5);
  EXPECT_GT(tiles.walkable, 0.85);
  EXPECT_NEAR(tiles.height, 0.0, 0.005);
  EXPECT_NEAR(tiles.friction, QuantileOf(scenario, "ceramic"), 0.01);
  EXPECT_EQ(Summarise(terrain, -0.6, -0.9, -0.4, 0.9).seen, 0.0);  // behind the camera's view
}

// The cloth is not walkable (materials.yaml): wherever the camera reconstructs it, the terrain says so. The box
// stands as raised ground where its top is reconstructed.
TEST(MainDiagramTest, PerceivesTheClothAsNotWalkableAndTheObstacleAsRaisedGround) {
  const TerrainMap cloth = Perceive(Build(Mockup("mockup_cloth.yaml")));
  const CellSummary on_cloth = Summarise(cloth, 0.325, -0.375, 0.675, -0.025);
  std::printf("cloth: seen %.2f, walkable %.2f\n", on_cloth.seen, on_cloth.walkable);
  EXPECT_GT(on_cloth.seen, 0.05);
  EXPECT_EQ(on_cloth.walkable, 0.0);
  const TerrainMap obstacle = Perceive(Build(Mockup("mockup_obstacle.yaml")));
  const CellSummary on_box = Summarise(obstacle, 0.45, -0.3, 0.6, -0.1);
  std::printf("box: seen %.2f, height %.3f m\n", on_box.seen, on_box.height);
  EXPECT_GT(on_box.seen, 0.2);
  EXPECT_NEAR(on_box.height, 0.12, 0.02);
}

// Thesis 5.2.3 through the whole diagram, perception included: RunMainDiagram perceives the first frame, hands the
// assembled terrain to the planner, and the plant walks what the chain settles on: a plan on the perceived
// terrain (its footholds at the perceived heights) walked to the goal without a fall. Slips are counted, not
// asserted: the plan uses all of the wood's friction quantile (docs/main_diagram.md).
TEST(MainDiagramTest, RunsThePerceptionThePlannerAndThePlantAsOneDiagram) {
  const FootstepScenario scenario = Mockup("mockup.yaml");
  const MainRecord record = RunWhole(scenario, 0.5);
  ASSERT_NE(record.terrain, nullptr);
  EXPECT_EQ(record.terrain->cols(), 96);
  EXPECT_EQ(record.terrain->rows(), 72);
  EXPECT_GE(record.perception_seconds, 0.0);
  const CellSummary wood = Summarise(*record.terrain, 0.3, 0.15, 1.1, 0.5);
  EXPECT_GT(wood.seen, 0.95);  // the planner read the perceived terrain, not the scenario's
  std::printf("%s: %s; %zu steps, %zu slips, perception %.2f s\n", scenario.name().c_str(),
              record.walk.start.ready ? "walked" : record.walk.start.reason.c_str(), record.walk.plan.steps.size(),
              record.walk.slips.size(), record.perception_seconds);
  ASSERT_TRUE(record.walk.start.ready) << record.walk.start.reason;
  EXPECT_GE(record.walk.plan.steps.size(), 4u);
  bool perceived_height = false;
  for (const PlannedStep& step : record.walk.plan.steps) perceived_height = perceived_height || step.pose.z != 0.0;
  EXPECT_TRUE(perceived_height) << "the footholds stand at the perceived heights, not the scenario's zero";
  EXPECT_FALSE(record.walk.fell) << record.walk.fall_reason << " at " << record.walk.duration << " s";
  ASSERT_FALSE(record.walk.samples.empty());
  EXPECT_GT(record.walk.samples.back().com.x(), 0.8) << "the robot walks the metre to the goal";
}

// Thesis 5.2.3's second situation through the whole diagram: a cloth (not walkable) on the tiles across the right
// foot's way. No sole of the plan made on the perceived terrain stands on the cloth (the plan leaves the tiles for
// the wood around it, as the thesis' robot did; a corner may reach one terrain cell over its perceived edge).
// Measured 2026-12-06: that plan is walked without a fall but ends 12 cm from the goal after 23 slips (before the
// stabiliser's landing phase it fell at about 7 s; docs/main_diagram.md), so the walk is printed, not asserted.
TEST(MainDiagramTest, NoFootOfThePlanLandsOnTheCloth) {
  const FootstepScenario scenario = Mockup("mockup_cloth.yaml");
  const MainRecord record = RunWhole(scenario, 0.2);
  ASSERT_TRUE(record.walk.start.ready) << record.walk.start.reason;
  const FootstepScenario::Region* cloth = nullptr;
  for (const auto& region : scenario.regions()) {
    if (region.name == "cloth") cloth = &region;
  }
  ASSERT_NE(cloth, nullptr);
  Eigen::Vector2d lo = cloth->polygon.front(), hi = lo;
  for (const Eigen::Vector2d& p : cloth->polygon) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  // How far into the cloth a sole reaches: over the sole sampled on a 9 x 5 grid, edges included, the largest
  // depth of a sample inside the cloth's box (0 outside).
  const BipedGeometry& geometry = WalkFor(scenario).geometry;
  double deepest = 0.0;
  int on_wood = 0;
  for (const PlannedStep& step : record.walk.plan.steps) {
    const Eigen::Vector2d ax(std::cos(step.pose.theta), std::sin(step.pose.theta)), ay(-ax.y(), ax.x());
    for (int i = -4; i <= 4; ++i) {
      for (int j = -2; j <= 2; ++j) {
        const Eigen::Vector2d q = Eigen::Vector2d(step.pose.x, step.pose.y) +
                                  (0.5 * geometry.foot_length * i / 4.0) * ax + (0.5 * geometry.foot_width * j / 2.0) * ay;
        deepest = std::max(deepest, std::min({q.x() - lo.x(), hi.x() - q.x(), q.y() - lo.y(), hi.y() - q.y()}));
      }
    }
    on_wood += step.pose.y > 0.0;
  }
  // Perception places the cloth's edge to within a terrain cell (2.5 cm): a sole's corner may reach that far in.
  EXPECT_LE(deepest, 0.025) << "a sole stands on the cloth";
  std::printf("%zu steps, %d with the sole's centre on the wood, %.3f m deepest into the cloth; walked %.2f s, %s, "
              "%zu slips\n",
              record.walk.plan.steps.size(), on_wood, deepest, record.walk.duration,
              record.walk.fell ? record.walk.fall_reason.c_str() : "no fall", record.walk.slips.size());
}

}  // namespace
}  // namespace cairn::planning
