// ScenarioTerrainBoxes: a footstep scenario's regions as non-overlapping plant boxes with their true friction.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include <cairn/planning/walk/scenario_terrain_boxes.h>

#include "expect_throws.h"
#include "test_paths.h"

namespace cairn::planning {
namespace {

namespace fs = std::filesystem;

FootstepScenario Write(const std::string& name, const std::string& regions, const std::string& extra = "") {
  const fs::path path = fs::temp_directory_path() / (name + "_" + std::to_string(::getpid()) + ".yaml");
  std::ofstream(path) << "name: " << name << R"(
terrain:
  min: [-1.0, -1.0]
  max: [3.0, 1.0]
  regions:
)" << regions << extra << R"(
start: {left: [0.0, 0.1, 0.0], right: [0.0, -0.1, 0.0]}
goal: {left: [1.0, 0.1, 0.0], right: [1.0, -0.1, 0.0]}
)";
  FootstepScenario scenario = FootstepScenario::Load(path.string());
  fs::remove(path);
  return scenario;
}

TEST(ScenarioTerrainBoxesTest, CutsTheGroundAroundTheIceSoEachFootTouchesOneFriction) {
  const FootstepScenario scenario = FootstepScenario::Load(std::string(CAIRN_SOURCE_DIR) +
                                                           "/examples/scenarios/ice_narrow_006.yaml");
  const auto boxes = ScenarioTerrainBoxes(scenario);
  ASSERT_EQ(boxes.size(), 5u);  // four pieces of ground around the ice, then the ice
  double area = 0.0;
  for (const auto& box : boxes) {
    area += box.size.x() * box.size.y();
    EXPECT_NEAR(box.X_WB.translation().z() + 0.5 * box.size.z(), 0.0, 1e-12) << box.name;  // top face at z = 0
  }
  EXPECT_NEAR(area, 4.0 * 4.0, 1e-9);  // the terrain's area, covered once
  EXPECT_EQ(boxes.back().name, "ice");
  EXPECT_DOUBLE_EQ(boxes.back().friction, 0.06);
  EXPECT_NEAR(boxes.back().X_WB.translation().x(), 1.5, 1e-12);
  EXPECT_EQ(boxes.front().name, "ground");
  EXPECT_DOUBLE_EQ(boxes.front().friction, 1.0);
}

TEST(ScenarioTerrainBoxesTest, ASlopedRegionsTopFaceLiesInItsPlane) {
  const FootstepScenario scenario =
      Write("ramp", "    - {name: ramp, box: {min: [0.0, -1.0], max: [2.0, 1.0]}, slope: {angle_deg: 10, uphill_deg: 0, origin: [0, 0]}, friction: 0.5}\n");
  const auto boxes = ScenarioTerrainBoxes(scenario);
  ASSERT_EQ(boxes.size(), 1u);
  const auto& box = boxes[0];
  const Eigen::Vector3d up = box.X_WB.rotation().col(2);
  EXPECT_NEAR(up.dot(scenario.regions()[0].Normal().normalized()), 1.0, 1e-12);
  const Eigen::Vector3d top = box.X_WB.translation() + 0.5 * box.size.z() * up;
  EXPECT_NEAR(top.z(), scenario.regions()[0].HeightAt(top.head<2>()), 1e-9);
  EXPECT_DOUBLE_EQ(box.friction, 0.5);
  // Uphill along y works the same; a diagonal uphill would leave gaps between the cut pieces, so it is refused.
  EXPECT_EQ(ScenarioTerrainBoxes(Write("side ramp", "    - {name: ramp, box: {min: [0.0, -1.0], max: [2.0, 1.0]}, "
                                                    "slope: {angle_deg: 10, uphill_deg: 90, origin: [0, 0]}, "
                                                    "friction: 0.5}\n"))
                .size(),
            1u);
  CAIRN_EXPECT_THROWS_WITH(
      ScenarioTerrainBoxes(Write("diagonal", "    - {name: ramp, box: {min: [0.0, -1.0], max: [2.0, 1.0]}, slope: "
                                             "{angle_deg: 10, uphill_deg: 45, origin: [0, 0]}, friction: 0.5}\n")),
      std::invalid_argument, "region 'ramp' slopes neither along x nor along y (uphill 45 deg)",
      "uphill_deg 0, 90, 180 or 270");
}

TEST(ScenarioTerrainBoxesTest, ObstaclesBecomeBoxesAndAPolygonIsRefused) {
  const FootstepScenario bar =
      Write("bar", "    - {name: floor, box: {min: [-1.0, -1.0], max: [3.0, 1.0]}, friction: 1.0}\n",
            "obstacles:\n  - {name: bar, min: [0.7, -1.0, 1.3], max: [0.8, 1.0, 1.4]}\n");
  const auto boxes = ScenarioTerrainBoxes(bar);
  ASSERT_EQ(boxes.size(), 2u);
  EXPECT_EQ(boxes[1].name, "bar");
  EXPECT_TRUE(boxes[1].size.isApprox(Eigen::Vector3d(0.1, 2.0, 0.1), 1e-12));
  const FootstepScenario triangle = Write(
      "triangle", "    - {name: floor, box: {min: [-1.0, -1.0], max: [3.0, 1.0]}, friction: 1.0}\n"
                  "    - {name: wedge, polygon: [[0, 0], [1, 0], [0, 1]], friction: 0.3}\n");
  CAIRN_EXPECT_THROWS_WITH(ScenarioTerrainBoxes(triangle), std::invalid_argument,
                           "region 'wedge' is a 3-gon that is not an axis-aligned rectangle");
}

}  // namespace
}  // namespace cairn::planning
