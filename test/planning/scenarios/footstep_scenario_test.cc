#include <cairn/planning/scenarios/footstep_scenario.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "expect_throws.h"

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
                           "slope_20", "slope_25"}) {
    const FootstepScenario scenario = FootstepScenario::Load(kScenarios + name + ".yaml");
    EXPECT_FALSE(scenario.name().empty()) << name;
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
      FootstepScenario::Load(Scratch("inf.yaml", std::string(text).replace(text.find("max: [2, 1]"), 11, "max: [.inf, 1]"))),
      std::invalid_argument, "line 4", "'max' must be a finite number, got '.inf'");
  CAIRN_EXPECT_THROWS_WITH(
      FootstepScenario::Load(Scratch("huge.yaml", std::string(text).replace(text.find("max: [2, 1]"), 11, "max: [1e5, 1e5]"))),
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

}  // namespace
}  // namespace cairn::planning
