#include <cairn/planning/scenarios/footstep_scenario.h>

#include <cmath>
#include <cstdio>
#include <chrono>
#include <fstream>
#include <initializer_list>
#include <string>

#include <gtest/gtest.h>

#include <cairn/planning/footstep/time_limit_reached.h>

#include "expect_throws.h"
#include "test_paths.h"

namespace cairn::planning {
namespace {

const std::string kScenarios = std::string(CAIRN_SOURCE_DIR) + "/examples/scenarios/";

// Writes `text` to a scratch file and returns its path.
std::string Scratch(const std::string& name, const std::string& text) {
  const std::string path = testing::TempDir() + name;
  std::ofstream(path) << text;
  return path;
}

const char* kMinimal = R"(name: minimal
terrain:
  min: [0, -1]
  max: [2, 1]
  regions:
    - {name: ground, box: {min: [0, -1], max: [2, 1]}, friction: 0.8}
start: {left: [0.2, 0.1, 0], right: [0.2, -0.1, 0]}
goal: {left: [1.5, 0.1, 0], right: [1.5, -0.1, 0]}
)";

TEST(FootstepScenarioTest, LoadsEveryExampleScenario) {
  for (const char* name : {"flat", "ice_narrow_012", "ice_narrow_006", "ice_wide_006", "stairs", "slope_10",
                           "slope_20", "slope_25", "flat_plant_oracle"}) {
    const FootstepScenario scenario = FootstepScenario::Load(kScenarios + name + ".yaml");
    EXPECT_FALSE(scenario.name().empty()) << name;
    // Every scenario prices its steps with the analytic model unless it names another source.
    EXPECT_EQ(scenario.oracle(), std::string(name) == "flat_plant_oracle" ? "plant" : "model") << name;
    const TerrainMap terrain = scenario.BuildTerrain();
    EXPECT_GT(terrain.cols() * terrain.rows(), 10000) << name;
  }
}

TEST(FootstepScenarioTest, RasterisesHeightsSlopesAndFrictionQuantiles) {
  {
    const FootstepScenario ice = FootstepScenario::Load(kScenarios + "ice_narrow_012.yaml");
    const TerrainMap terrain = ice.BuildTerrain();
    int c, r;
    ASSERT_TRUE(terrain.CellAt(1.5, 0.0, &c, &r));
    EXPECT_NEAR(terrain.friction(c, r), 0.12, 1e-6);
    ASSERT_TRUE(terrain.CellAt(1.5, 1.5, &c, &r));
    EXPECT_NEAR(terrain.friction(c, r), 1.0, 1e-6);
    EXPECT_NEAR(ice.goal().stance.left.x, 3.0, 1e-12);
    EXPECT_NEAR(ice.planner().search.time_limit, 10.0, 1e-12);
  }
  {
    const FootstepScenario slope = FootstepScenario::Load(kScenarios + "slope_20.yaml");
    const TerrainMap terrain = slope.BuildTerrain();
    int c, r;
    ASSERT_TRUE(terrain.CellAt(2.0, 0.3, &c, &r));
    const Eigen::Vector2d centre = terrain.CellCenter(c, r);
    EXPECT_NEAR(terrain.height(c, r), std::tan(20.0 * M_PI / 180.0) * centre.x(), 1e-5);
    EXPECT_NEAR(std::acos(terrain.normal(c, r).z()), 20.0 * M_PI / 180.0, 1e-6);
  }
  {
    // asphalt ~ N(0.74, 0.12): Q_0.05 = 0.74 - 1.6449 * 0.12.
    const FootstepScenario flat = FootstepScenario::Load(kScenarios + "flat.yaml");
    const TerrainMap terrain = flat.BuildTerrain();
    int c, r;
    ASSERT_TRUE(terrain.CellAt(1.0, 0.0, &c, &r));
    EXPECT_NEAR(terrain.friction(c, r), 0.74 - 1.6448536 * 0.12, 1e-5);
  }
  {
    const FootstepScenario stairs = FootstepScenario::Load(kScenarios + "stairs.yaml");
    const TerrainMap terrain = stairs.BuildTerrain();
    int c, r;
    ASSERT_TRUE(terrain.CellAt(1.1, -0.5, &c, &r));
    EXPECT_NEAR(terrain.height(c, r), 0.07, 1e-6);
    ASSERT_TRUE(terrain.CellAt(1.1, 0.0, &c, &r));
    EXPECT_FALSE(terrain.has_ground(c, r)) << "the wall between the stairs has no ground";
    EXPECT_EQ(terrain.obstacles().size(), 3u);
  }
}

TEST(FootstepScenarioTest, ErrorsNameTheFileLineAndKey) {
  std::string text = kMinimal;
  CAIRN_EXPECT_THROWS_WITH(
      FootstepScenario::Load(Scratch("typo.yaml", std::string(text).replace(text.find("goal:"), 5, "gaol:"))),
      std::invalid_argument, "typo.yaml' line 8", "unknown key 'gaol'", "Did you mean 'goal'?");
  CAIRN_EXPECT_THROWS_WITH(
      FootstepScenario::Load(Scratch("eta.yaml", text + "eta: 1.5\n")), std::invalid_argument, "eta.yaml' line 9",
      "eta must be in (0, 1)", "1.5");
  CAIRN_EXPECT_THROWS_WITH(
      FootstepScenario::Load(Scratch("mu.yaml", std::string(text).replace(text.find("friction: 0.8"), 13,
                                                                          "friction: {distribution: normal, mean: 0.5}"))),
      std::invalid_argument, "line 6", "missing key 'stddev'", "region 1 ('ground')");
  CAIRN_EXPECT_THROWS_WITH(
      FootstepScenario::Load(Scratch("material.yaml", std::string(text).replace(text.find("friction: 0.8"), 13,
                                                                                "material: asfalt"))),
      std::invalid_argument, "line 6", "asfalt", "asphalt");
  CAIRN_EXPECT_THROWS_WITH(
      FootstepScenario::Load(Scratch("foot.yaml", std::string(text).replace(text.find("[0.2, 0.1, 0]"), 13, "[0.2, 0.1]"))),
      std::invalid_argument, "line 7", "'left' must be a list of 3 numbers", "[0.2, 0.1]");
  CAIRN_EXPECT_THROWS_WITH(
      FootstepScenario::Load(Scratch("planner.yaml", text + "planner: {orientations: 64}\n")), std::invalid_argument,
      "line 9", "planner 'orientations' must be an integer in [1, 32], got 64");
  CAIRN_EXPECT_THROWS_WITH(FootstepScenario::Load(Scratch("lattice.yaml", text + "planner: {lattice: 1e-12}\n")),
                           std::invalid_argument, "line 9", "planner 'lattice' must be in [0.01, 0.5] m");
  CAIRN_EXPECT_THROWS_WITH(
      FootstepScenario::Load(Scratch("level.yaml", text + "planner: {level_step_tolerance: -0.01}\n")),
      std::invalid_argument, "line 9", "planner 'level_step_tolerance' must be in [0, 1] m, got -0.01");
  EXPECT_EQ(FootstepScenario::Load(Scratch("level_ok.yaml", text + "planner: {level_step_tolerance: 0.01}\n"))
                .planner()
                .level_step_tolerance,
            0.01);
  CAIRN_EXPECT_THROWS_WITH(
      FootstepScenario::Load(Scratch("inf.yaml", std::string(text).replace(text.find("max: [2, 1]"), 11, "max: [.inf, 1]"))),
      std::invalid_argument, "line 4", "'max' must be a finite number, got '.inf'");
  CAIRN_EXPECT_THROWS_WITH(
      FootstepScenario::Load(Scratch("huge.yaml", std::string(text).replace(text.find("max: [2, 1]"), 11, "max: [9e3, 9e3]"))),
      std::invalid_argument, "at most 5e+07 are supported");
  CAIRN_EXPECT_THROWS_WITH(
      FootstepScenario::Load(Scratch("nan.yaml", std::string(text).replace(text.find("[1.5, 0.1, 0]"), 13, "[1.5, 0.1, .nan]"))),
      std::invalid_argument, "line 8", "'left' must be a finite number, got '.nan'");
  CAIRN_EXPECT_THROWS_WITH(FootstepScenario::Load(Scratch("twice.yaml", text + "name: again\n")), std::invalid_argument,
                           "twice.yaml' line 9", "the key 'name' appears twice in one mapping (first at line 1)");
  CAIRN_EXPECT_THROWS_WITH(FootstepScenario::Load(Scratch("broken.yaml", "name: [unclosed\n")), std::invalid_argument,
                           "Malformed YAML in", "broken.yaml");
  CAIRN_EXPECT_THROWS_WITH(FootstepScenario::Load("/nonexistent/scenario.yaml"), std::invalid_argument,
                           "Cannot read '/nonexistent/scenario.yaml'");
}

// Loads `text` from a scratch file and expects std::invalid_argument naming the file, `line` and every part; a
// message about a scenario file never names the raster's internals.
void ExpectRefused(const std::string& name, const std::string& text, int line,
                   std::initializer_list<std::string> parts) {
  const std::string path = Scratch(name, text);
  try {
    FootstepScenario::Load(path);
    ADD_FAILURE() << name << " was accepted";
  } catch (const std::invalid_argument& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("In '" + path + "' line " + std::to_string(line) + ":"), std::string::npos) << message;
    for (const std::string& part : parts) EXPECT_NE(message.find(part), std::string::npos) << message;
    EXPECT_EQ(message.find("TerrainMap"), std::string::npos) << message;
    EXPECT_EQ(message.find("SetCell"), std::string::npos) << message;
  }
}

std::string With(const std::string& from, const std::string& to) {
  std::string text = kMinimal;
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return text.replace(at, from.size(), to);
}

TEST(FootstepScenarioTest, RefusesPhysicallyMeaninglessValues) {
  ExpectRefused("mu_huge.yaml", With("friction: 0.8", "friction: 1e6"), 6,
                {"region 1 ('ground')", "friction must be a coefficient in (0, 10]", "got 1e+06"});
  ExpectRefused("mu_zero.yaml", With("friction: 0.8", "friction: 0"), 6, {"(0, 10]", "not_walkable"});
  ExpectRefused("mu_mean.yaml", With("friction: 0.8", "friction: {distribution: normal, mean: 1e6, stddev: 0.1}"), 6,
                {"region 1 ('ground')", "the mean 1e+06 is outside (0, 10]"});
  ExpectRefused("height.yaml", With("friction: 0.8}", "friction: 0.8, height: 1e9}"), 6,
                {"'height' must be in [-100, 100] m", "got 1e+09"});
  ExpectRefused("slope.yaml",
                With("friction: 0.8}", "friction: 0.8, slope: {angle_deg: 60, origin: [-9000, 0]}}"), 6,
                {"the slope puts vertex (0, -1) at height", "beyond +-100 m"});
  ExpectRefused("outside.yaml", With("box: {min: [0, -1], max: [2, 1]}", "box: {min: [5, -1], max: [7, 1]}"), 6,
                {"region 1 ('ground') spans x [5, 7]", "wholly outside the terrain's x [0, 2]"});
  ExpectRefused("nan_vertex.yaml", With("box: {min: [0, -1], max: [2, 1]}", "polygon: [[0, -1], [2, .nan], [2, 1]]"),
                6, {"'polygon vertex' must be a finite number, got '.nan'"});
  ExpectRefused("far_vertex.yaml", With("box: {min: [0, -1], max: [2, 1]}", "polygon: [[0, -1], [2, 2e4], [2, 1]]"),
                6, {"region 1 ('ground')'s polygon", "'vertex' must be in [-10000, 10000] m, got 20000"});
  ExpectRefused("crossed.yaml", With("left: [0.2, 0.1, 0], right: [0.2, -0.1, 0]", "left: [0.2, -0.1, 0], right: [0.2, 0.1, 0]"),
                7, {"start: the left foot at (0.2, -0.1) is not to the left of the right foot", "crossed"});
  ExpectRefused("one_point.yaml", With("left: [1.5, 0.1, 0], right: [1.5, -0.1, 0]", "left: [1.5, 0, 0], right: [1.5, 0, 0]"),
                8, {"goal: both feet stand at one point"});
  ExpectRefused("obstacle_nan.yaml", std::string(kMinimal) + "obstacles:\n  - {min: [1, 0, 0], max: [1.2, .nan, 1]}\n", 10,
                {"'max' must be a finite number, got '.nan'"});
  ExpectRefused("obstacle_far.yaml", std::string(kMinimal) + "obstacles:\n  - {min: [1, 0, 0], max: [1.2, 2e4, 1]}\n", 10,
                {"obstacle 1", "'max' must be in [-10000, 10000] m, got 20000"});
  ExpectRefused("obstacle_high.yaml", std::string(kMinimal) + "obstacles:\n  - {min: [1, 0, 0], max: [1.2, 0.2, 1e9]}\n",
                10, {"obstacle 1", "'max's z' must be in [-100, 100] m"});
  ExpectRefused("tolerance.yaml", std::string(kMinimal).replace(std::string(kMinimal).find("[1.5, -0.1, 0]}"), 15,
                                                                 "[1.5, -0.1, 0], tolerance: .inf}"),
                8, {"'tolerance' must be a finite number, got '.inf'"});
  ExpectRefused("tolerance_wide.yaml", std::string(kMinimal).replace(std::string(kMinimal).find("[1.5, -0.1, 0]}"), 15,
                                                                      "[1.5, -0.1, 0], tolerance: 50}"),
                8, {"goal: 'tolerance' must be in [0, 10] m, got 50"});
  ExpectRefused("epsilon.yaml", std::string(kMinimal) + "planner: {initial_epsilon: .inf}\n", 9,
                {"'initial_epsilon' must be a finite number, got '.inf'"});
  ExpectRefused("epsilon_huge.yaml", std::string(kMinimal) + "planner: {initial_epsilon: 1000}\n", 9,
                {"planner 'initial_epsilon' must be in [1, 100], got 1000"});
}

TEST(FootstepScenarioTest, CountsAreBoundedBeforeAnythingIsBuilt) {
  std::string obstacles = std::string(kMinimal) + "obstacles:\n";
  for (std::size_t k = 0; k <= FootstepScenario::kMaxObstacles; ++k) {
    obstacles += "  - {min: [1, 0, 0], max: [1.01, 0.01, 1]}\n";
  }
  ExpectRefused("obstacles.yaml", obstacles, 10, {"'obstacles' lists 1001 boxes; at most 1000 are supported"});
  std::string regions = With("    - {name: ground, box: {min: [0, -1], max: [2, 1]}, friction: 0.8}\n", "");
  std::string list;
  for (std::size_t k = 0; k <= FootstepScenario::kMaxRegions; ++k) {
    list += "    - {box: {min: [0, -1], max: [2, 1]}, friction: 0.8}\n";
  }
  regions.insert(regions.find("start:"), list);
  ExpectRefused("regions.yaml", regions, 6, {"terrain 'regions' must be a list of 1 to 1000 regions, got 1001"});
  std::string polygon = "[[0, -1]";
  for (std::size_t k = 0; k < FootstepScenario::kMaxPolygonVertices; ++k) polygon += ", [2, " + std::to_string(k * 1e-4) + "]";
  polygon += "]";
  ExpectRefused("polygon.yaml", With("box: {min: [0, -1], max: [2, 1]}", "polygon: " + polygon), 6,
                {"polygon must be a list of 3 to 1000 [x, y] vertices, got 1001"});
}

TEST(FootstepScenarioTest, RasterisingHonoursADeadline) {
  const FootstepScenario scenario = FootstepScenario::Load(Scratch("deadline.yaml", kMinimal));
  EXPECT_NO_THROW(scenario.BuildTerrain(std::chrono::steady_clock::now() + std::chrono::hours(1)));
  CAIRN_EXPECT_THROWS_WITH(scenario.BuildTerrain(std::chrono::steady_clock::now() - std::chrono::seconds(1)),
                           TimeLimitReached, "while rasterising the terrain of '", "deadline.yaml",
                           "region 1 of 1", "80 x 80 cells");
  // Painting each region over its bounding box only gives the same raster as testing every region everywhere.
  const FootstepScenario stairs = FootstepScenario::Load(kScenarios + "stairs.yaml");
  const TerrainMap terrain = stairs.BuildTerrain();
  for (int r = 0; r < terrain.rows(); r += 7) {
    for (int c = 0; c < terrain.cols(); c += 5) {
      const Eigen::Vector2d p = terrain.CellCenter(c, r);
      const FootstepScenario::Region* top = nullptr;
      for (const auto& region : stairs.regions()) {
        if (region.Contains(p)) top = &region;
      }
      bool under_obstacle = false;
      for (const auto& o : stairs.obstacles()) {
        const Eigen::Vector2d d = p - o.center.head<2>();
        const double lx = std::cos(o.yaw) * d.x() + std::sin(o.yaw) * d.y();
        const double ly = -std::sin(o.yaw) * d.x() + std::cos(o.yaw) * d.y();
        under_obstacle = under_obstacle || (std::abs(lx) <= o.half_extents.x() && std::abs(ly) <= o.half_extents.y());
      }
      if (under_obstacle) continue;
      ASSERT_EQ(terrain.has_ground(c, r), top != nullptr) << p.transpose();
      if (top != nullptr) {
        EXPECT_NEAR(terrain.height(c, r), top->HeightAt(p), 1e-5);
      }
    }
  }
}

}  // namespace
}  // namespace cairn::planning
