// A footstep scenario as the synthetic head camera sees it: where the camera is, what each region looks like, and
// the errors for scenarios a camera cannot see.
#include <gtest/gtest.h>

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include <cairn/perception/synthetic/material_texture.h>
#include <cairn/planning/run/scenario_stereo_scene.h>

#include "expect_throws.h"
#include "test_paths.h"

namespace cairn::planning {
namespace {

namespace fs = std::filesystem;

FootstepScenario Mockup(const std::string& name = "mockup.yaml") {
  return FootstepScenario::Load(std::string(CAIRN_SOURCE_DIR) + "/examples/scenarios/mockup/" + name);
}

FootstepScenario FromText(const std::string& text) {
  const fs::path path = fs::temp_directory_path() / ("scenario_stereo_scene_" + std::to_string(::getpid()) + ".yaml");
  std::ofstream(path) << text;
  FootstepScenario scenario = FootstepScenario::Load(path.string());
  fs::remove(path);
  return scenario;
}

int LabelOf(const std::string& material) {
  const auto& labels = perception::MaterialTexture::SupportedLabels();
  return static_cast<int>(std::find(labels.begin(), labels.end(), material) - labels.begin());
}

TEST(ScenarioCameraPoseTest, LooksDownAlongTheHeadingFromAboveTheStance) {
  Stance start;
  start.left = FootPose{1.0, 2.1, 0.2, M_PI / 2};
  start.right = FootPose{1.0, 1.9, 0.2, M_PI / 2};
  HeadCamera head;
  head.height = 1.5;
  head.pitch_deg = 60.0;
  head.behind = 0.1;
  const Eigen::Isometry3d X_WC = ScenarioCameraPose(start, head);
  EXPECT_TRUE(X_WC.linear().isUnitary(1e-12));
  EXPECT_NEAR(X_WC.linear().determinant(), 1.0, 1e-12);
  // Heading +y: the camera stands 0.1 m behind (at y = 1.9) and 1.5 m above the stance.
  EXPECT_TRUE(X_WC.translation().isApprox(Eigen::Vector3d(1.0, 1.9, 1.7), 1e-12));
  // The optical axis (camera z) points along +y, 60 degrees below the horizon; image x is to the robot's right (+x
  // of the world here) and image y points down and forward.
  const Eigen::Vector3d axis = X_WC.linear().col(2);
  EXPECT_NEAR(axis.z(), -std::sin(M_PI / 3), 1e-12);
  EXPECT_NEAR(axis.y(), std::cos(M_PI / 3), 1e-12);
  EXPECT_NEAR(X_WC.linear().col(0).x(), 1.0, 1e-12);
  EXPECT_LT(X_WC.linear().col(1).z(), 0.0);
}

TEST(ScenarioCameraPoseTest, RejectsOptionsOutOfRange) {
  HeadCamera head;
  head.pitch_deg = 95.0;
  CAIRN_EXPECT_THROWS_WITH(ScenarioCameraPose(Stance(), head), std::invalid_argument, "pitch_deg must be in (0, 90]");
  head = HeadCamera();
  head.height = 0.0;
  CAIRN_EXPECT_THROWS_WITH(ScenarioCameraPose(Stance(), head), std::invalid_argument, "height must be in (0, 10]");
}

// Rays down from above each region meet that region's material, and the cloth lies on (above) the tiles.
TEST(ScenarioStereoSceneTest, EachRegionShowsItsMaterialAndLaterRegionsLieOnEarlierOnes) {
  const perception::SyntheticStereoScene scene = ScenarioStereoScene(Mockup("mockup_cloth.yaml"));
  EXPECT_TRUE(scene.has_colour_textures());
  const auto label_below = [&](double x, double y) {
    const auto hit = scene.Intersect(Eigen::Vector3d(x, y, 2.0), -Eigen::Vector3d::UnitZ());
    EXPECT_TRUE(hit.has_value()) << x << ", " << y;
    return hit ? std::make_pair(hit->label, 2.0 - hit->t) : std::make_pair(-1, 0.0);
  };
  EXPECT_EQ(label_below(0.2, 0.3).first, LabelOf("wood"));
  EXPECT_EQ(label_below(0.2, -0.3).first, LabelOf("ceramic"));
  const auto [cloth, cloth_top] = label_below(0.5, -0.2);
  EXPECT_EQ(cloth, LabelOf("cloth"));
  const auto [tiles, tiles_top] = label_below(0.1, -0.2);
  EXPECT_NEAR(tiles_top, 0.0, 1e-12);
  EXPECT_GT(cloth_top, tiles_top);
  EXPECT_LT(cloth_top, 0.005);
  // Beyond the regions: the floor, below them.
  const auto [floor, floor_top] = label_below(3.0, 0.0);
  EXPECT_EQ(floor, LabelOf("asphalt"));
  EXPECT_LT(floor_top, -0.02);
}

TEST(ScenarioStereoSceneTest, ObstaclesAreBoxesOfTheirMaterial) {
  const perception::SyntheticStereoScene scene = ScenarioStereoScene(Mockup("mockup_obstacle.yaml"), 1, "wood");
  const auto hit = scene.Intersect(Eigen::Vector3d(0.5, -0.2, 2.0), -Eigen::Vector3d::UnitZ());
  ASSERT_TRUE(hit.has_value());
  EXPECT_EQ(hit->label, LabelOf("wood"));
  EXPECT_NEAR(2.0 - hit->t, 0.12, 1e-12);
}

TEST(ScenarioStereoSceneTest, NamesTheRegionsACameraCannotSee) {
  const std::string head = "name: t\nterrain:\n  min: [-1, -1]\n  max: [1, 1]\n  regions:\n";
  const std::string tail = "start: {left: [0, 0.1, 0], right: [0, -0.1, 0]}\ngoal: {left: [0.5, 0.1, 0], right: [0.5, -0.1, "
                           "0], tolerance: 0.1}\n";
  CAIRN_EXPECT_THROWS_WITH(
      ScenarioStereoScene(FromText(head + "    - {name: ice, box: {min: [-1, -1], max: [1, 1]}, friction: 0.1}\n" + tail)),
      std::invalid_argument, "region 'ice' states a friction, not a material");
  CAIRN_EXPECT_THROWS_WITH(
      ScenarioStereoScene(FromText(head + "    - {name: lawn, box: {min: [-1, -1], max: [1, 1]}, material: grass}\n" + tail),
                          1, "unobtainium"),
      std::invalid_argument, "an obstacle has material 'unobtainium', which has no texture");
  CAIRN_EXPECT_THROWS_WITH(
      ScenarioStereoScene(FromText(head + "    - {name: ramp, box: {min: [-1, -1], max: [1, 1]}, material: wood, "
                                          "slope: {angle_deg: 5}}\n" + tail)),
      std::invalid_argument, "region 'ramp' slopes");
}

TEST(SyntheticCameraTest, CalibrationFollowsTheOptics) {
  SyntheticCamera camera;
  camera.width = 200;
  camera.height = 100;
  camera.field_of_view_deg = 90.0;
  const perception::StereoCalibration calibration = camera.Calibration();
  EXPECT_NEAR(calibration.fx, 100.0, 1e-9);
  EXPECT_NEAR(calibration.fy, 100.0, 1e-9);
  EXPECT_NEAR(calibration.cx, 99.5, 1e-12);
  EXPECT_NEAR(calibration.cy, 49.5, 1e-12);
  EXPECT_NEAR(calibration.baseline, 0.12, 1e-12);
  camera.baseline = 0.0;
  CAIRN_EXPECT_THROWS_WITH(camera.Calibration(), std::invalid_argument, "baseline must be in (0, 1]");
}

}  // namespace
}  // namespace cairn::planning
