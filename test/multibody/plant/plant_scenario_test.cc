// PlantScenario: the terrain boxes and start height of `cairn simulate`, read with one-line errors.

#include <cmath>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include <cairn/multibody/plant/plant_scenario.h>

#include "expect_throws.h"
#include "test_paths.h"

namespace cairn::multibody {
namespace {

std::string Write(const std::string& name, const std::string& text) {
  const std::string path = std::string(CAIRN_BINARY_DIR) + "/" + name;
  std::ofstream(path) << text;
  return path;
}

TEST(PlantScenarioTest, ReadsTheShippedIceAndCarpetScenario) {
  const PlantScenario scenario =
      PlantScenario::Load(std::string(CAIRN_SOURCE_DIR) + "/examples/scenarios/plant/ice_and_carpet.yaml");
  ASSERT_EQ(scenario.terrain.size(), 2u);
  EXPECT_EQ(scenario.terrain[0].name, "ice");
  EXPECT_DOUBLE_EQ(scenario.terrain[0].friction, 0.1);
  EXPECT_DOUBLE_EQ(scenario.terrain[1].friction, 0.6);
  EXPECT_DOUBLE_EQ(scenario.drop_height, 0.05);
}

TEST(PlantScenarioTest, AppliesRollPitchYaw) {
  const PlantScenario scenario = PlantScenario::Load(
      Write("plant_slope.yaml", "terrain:\n  - {name: slope, center: [0, 0, -0.5], size: [4, 4, 1], rpy_deg: [0, 25, 0], "
                                "friction: 0.1}\n"));
  const Eigen::Matrix3d& R = scenario.terrain[0].X_WB.rotation();
  EXPECT_NEAR(R(2, 2), std::cos(25.0 * 3.14159265358979323846 / 180.0), 1e-12);
  EXPECT_NEAR(R(0, 2), std::sin(25.0 * 3.14159265358979323846 / 180.0), 1e-12);
}

TEST(PlantScenarioTest, RejectsBadFiles) {
  CAIRN_EXPECT_THROWS_WITH(PlantScenario::Load(Write("plant_empty.yaml", "terrain: []\n")), std::invalid_argument,
                           "non-empty list");
  CAIRN_EXPECT_THROWS_WITH(
      PlantScenario::Load(Write("plant_mu.yaml", "terrain:\n  - {name: a, center: [0, 0, 0], size: [1, 1, 1], "
                                                 "friction: 11}\n")),
      std::invalid_argument, "terrain[0].friction 11 is outside [0, 10]");
  CAIRN_EXPECT_THROWS_WITH(
      PlantScenario::Load(Write("plant_size.yaml", "terrain:\n  - {name: a, center: [0, 0, 0], size: [1, -1, 1], "
                                                   "friction: 1}\n")),
      std::invalid_argument, "terrain[0].size[1] = -1");
  CAIRN_EXPECT_THROWS_WITH(
      PlantScenario::Load(Write("plant_twice.yaml", "terrain:\n  - {name: a, center: [0, 0, 0], size: [1, 1, 1], "
                                                    "friction: 1}\n  - {name: a, center: [0, 0, 0], size: [1, 1, 1], "
                                                    "friction: 1}\n")),
      std::invalid_argument, "repeats the name 'a'");
  CAIRN_EXPECT_THROWS_WITH(PlantScenario::Load(Write("plant_drop.yaml", "drop_height: 5\nterrain: []\n")),
                           std::invalid_argument, "drop_height 5 m is outside [0, 2] m");
}

}  // namespace
}  // namespace cairn::multibody
