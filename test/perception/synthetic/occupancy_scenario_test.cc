#include "cairn/perception/synthetic/occupancy_scenario.h"

#include <cmath>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "cairn/perception/evaluation/occupancy_score.h"
#include "cairn/perception/occupancy/occupancy_grid.h"
#include "cairn/perception/synthetic/bars_scenario.h"
#include "expect_throws.h"

namespace cairn::perception {
namespace {

// A small valid scenario; the error tests replace one line of it.
const char* const kValid = R"(camera:
  width: 64
  height: 48
  fx: 60
  baseline: 0.2
stereo:
  min_disparity: 2
  max_disparity: 20
noise_variance: 4
textures:
  crate: {kind: noise, scale: 0.04, mean: 150, contrast: 70, seed: 11}
objects:
  - type: plane
    point: [0, 0, 0]
    normal: [0, 0, 1]
    texture: {kind: checker, scale: 0.5}
    label: 3
  - type: box
    center: [0, 3, 0.25]
    half_extents: [0.25, 0.25, 0.25]
    rotation_rpy_deg: [0, 0, 90]
    texture: crate
    label: 1
trajectory:
  orbit:
    center: [0, 3, 0.25]
    radius: 3
    height: 0.5
    start_deg: -10
    end_deg: 10
    frames: 3
grid:
  min_corner: [-1, 2, -0.1]
  resolution: 0.1
  dims: [20, 20, 8]
)";

std::string Write(const std::string& name, const std::string& text) {
  const std::string path = ::testing::TempDir() + "/occupancy_scenario_" + name;
  std::ofstream(path) << text;
  return path;
}

std::string Replace(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return text.replace(at, from.size(), to);
}

TEST(OccupancyScenarioTest, ReadsEverySection) {
  const auto s = OccupancyScenario::FromYaml(Write("valid.yaml", kValid));
  EXPECT_EQ(s.width, 64);
  EXPECT_EQ(s.height, 48);
  EXPECT_DOUBLE_EQ(s.calibration.fx, 60.0);
  EXPECT_DOUBLE_EQ(s.calibration.fy, 60.0);  // defaults to fx
  EXPECT_DOUBLE_EQ(s.calibration.cx, 31.5);  // image centre
  EXPECT_DOUBLE_EQ(s.calibration.cy, 23.5);
  EXPECT_DOUBLE_EQ(s.calibration.baseline, 0.2);
  EXPECT_EQ(s.min_disparity, 2);
  EXPECT_EQ(s.max_disparity, 20);
  EXPECT_DOUBLE_EQ(s.noise_variance, 4.0);
  EXPECT_EQ(s.scene.num_objects(), 2);
  ASSERT_EQ(s.trajectory.size(), 3u);
  // The orbit: angle -10, 0, 10 degrees at radius 3 around (0, 3, 0.25), 0.5 m higher, looking at the centre.
  const Eigen::Vector3d middle = s.trajectory[1].translation();
  EXPECT_TRUE(middle.isApprox(Eigen::Vector3d(0.0, 0.0, 0.75), 1e-12));
  const Eigen::Vector3d forward = s.trajectory[1].linear().col(2);
  EXPECT_TRUE(forward.isApprox((Eigen::Vector3d(0.0, 3.0, 0.25) - middle).normalized(), 1e-12));
  EXPECT_LT(s.trajectory[1].linear().col(1).z(), 0.0);  // image y points down
  EXPECT_NEAR(s.trajectory[0].translation().x(), -3.0 * std::sin(10.0 * M_PI / 180.0), 1e-12);
  EXPECT_TRUE(s.grid_min_corner.isApprox(Eigen::Vector3d(-1.0, 2.0, -0.1)));
  EXPECT_DOUBLE_EQ(s.grid_resolution, 0.1);
  EXPECT_EQ(s.grid_dims, Eigen::Vector3i(20, 20, 8));
  // The camera sees the box: the centre pixel of the middle frame hits it, 2.75 m away along the ray.
  const auto hit = s.scene.Intersect(middle, forward);
  ASSERT_TRUE(hit.has_value());
  EXPECT_EQ(hit->label, 1);
  // Ground truth on the grid: the box (5 x 5 x 3 cells, touching neighbours counted) and the floor layer.
  OccupancyGrid grid(s.grid_min_corner, s.grid_resolution, s.grid_dims);
  const auto truth = RasterizeScene(s.scene, grid);
  EXPECT_EQ(truth[grid.Index(*grid.CellOf(Eigen::Vector3d(0.0, 3.0, 0.25)))], 1);
  EXPECT_EQ(truth[grid.Index(*grid.CellOf(Eigen::Vector3d(0.0, 2.5, 0.45)))], 0);
}

TEST(OccupancyScenarioTest, ExplicitPosesAndTheBarsScenarioAgree) {
  std::string text = Replace(kValid, R"(  orbit:
    center: [0, 3, 0.25]
    radius: 3
    height: 0.5
    start_deg: -10
    end_deg: 10
    frames: 3
)",
                             R"(  poses:
    - {position: [0, 0, 0.75], look_at: [0, 3, 0.25]}
    - {position: [1, 0, 0.75], look_at: [0, 3, 0.25]}
)");
  const auto s = OccupancyScenario::FromYaml(Write("poses.yaml", text));
  ASSERT_EQ(s.trajectory.size(), 2u);
  EXPECT_TRUE(s.trajectory[1].translation().isApprox(Eigen::Vector3d(1.0, 0.0, 0.75)));
  // LookAt reproduces the bars scenario's hand-built poses.
  const BarsScenario bars = BarsScenario::Make(3);
  const Eigen::Isometry3d X = OccupancyScenario::LookAt(bars.trajectory[0].translation(), Eigen::Vector3d(0, 3, 0));
  EXPECT_TRUE(X.isApprox(bars.trajectory[0], 1e-12));
  const OccupancyScenario b = bars.ToOccupancyScenario();
  EXPECT_EQ(b.trajectory.size(), 3u);
  EXPECT_EQ(b.width, bars.width);
  EXPECT_EQ(b.max_disparity, bars.max_disparity);
}

TEST(OccupancyScenarioTest, ErrorsNameTheFileTheKeyAndTheLine) {
  auto expect_error = [](const std::string& name, const std::string& text, const std::string& key, int line) {
    const std::string path = Write(name, text);
    CAIRN_EXPECT_THROWS_WITH(OccupancyScenario::FromYaml(path), std::invalid_argument,
                             "In '" + path + "' line " + std::to_string(line) + ": " + key);
  };
  expect_error("negative.yaml", Replace(kValid, "[0.25, 0.25, 0.25]", "[0.25, -0.25, 0.25]"),
               "'objects[1].half_extents'", 20);
  expect_error("typo.yaml", Replace(kValid, "  baseline: 0.2", "  basline: 0.2"), "unknown key 'basline' in 'camera'",
               5);
  expect_error("missing.yaml", Replace(kValid, "  fx: 60\n", ""), "'camera.fx'", 2);
  expect_error("type.yaml", Replace(kValid, "  width: 64", "  width: wide"), "'camera.width'", 2);
  expect_error("texture.yaml", Replace(kValid, "    texture: crate", "    texture: crates"), "'objects[1].texture'",
               22);
  expect_error("kind.yaml", Replace(kValid, "  - type: box", "  - type: sphere"), "'objects[1].type'", 18);
  expect_error("range.yaml", Replace(kValid, "max_disparity: 20", "max_disparity: 64"), "'stereo.max_disparity'", 8);
  expect_error("dims.yaml", Replace(kValid, "[20, 20, 8]", "[20, 20]"), "'grid.dims'", 35);
  expect_error("both.yaml", Replace(kValid, "trajectory:\n", "trajectory:\n  poses: []\n"), "'trajectory'", 25);
  expect_error("twice.yaml", Replace(kValid, "  baseline: 0.2", "  baseline: 0.2\n  fx: 70"),
               "the key 'fx' appears twice in one mapping (first at line 4)", 6);

  // Counts are bounded before anything is built from them (100000000 frames took more than 4 GB of poses).
  expect_error("frames.yaml", Replace(kValid, "frames: 3", "frames: 100000000"), "'trajectory.orbit.frames' must be an integer in [1, 10000]", 31);
  expect_error("width.yaml", Replace(kValid, "  width: 64", "  width: 100000"), "'camera.width' must be an integer in [16, 8192]", 2);
  expect_error("seed.yaml", Replace(kValid, "seed: 11", "seed: 1099511627776"), "'textures.crate.seed' must be an integer in [0, 4294967295]", 11);
  expect_error("far.yaml", Replace(kValid, "center: [0, 3, 0.25]\n    half", "center: [0, 3e300, 0.25]\n    half"),
               "'objects[1].center[1]' is 3e+300, beyond the +-10000", 19);
  expect_error("noise.yaml", Replace(kValid, "noise_variance: 4", "noise_variance: 1e9"), "'noise_variance' must be in [0, 65025]", 9);
  std::string many = kValid;
  std::string poses = "trajectory:\n  poses:\n";
  for (int k = 0; k <= OccupancyScenario::kMaxFrames; ++k) poses += "    - {position: [0, 0, 1], look_at: [0, 3, 0]}\n";
  many = Replace(many, many.substr(many.find("trajectory:"), many.find("grid:") - many.find("trajectory:")), poses);
  expect_error("poses.yaml", many, "'trajectory.poses' has 10001 entries, more than the 10000", 26);
  const std::string wide_seed = Write("wide_seed.yaml", Replace(kValid, "seed: 11", "seed: 4294967296"));
  CAIRN_EXPECT_THROWS_WITH(OccupancyScenario::FromYaml(wide_seed), std::invalid_argument, "[0, 4294967295]",
                           "got '4294967296'");
  EXPECT_EQ(OccupancyScenario::FromYaml(Write("top_seed.yaml", Replace(kValid, "seed: 11", "seed: 4294967295")))
                .scene.num_objects(),
            2);
  CAIRN_EXPECT_THROWS_WITH(BarsScenario::Make(100000000), std::invalid_argument, "100000000 frames",
                           "1 to 10000");

  const std::string typo = Write("suggest.yaml", Replace(kValid, "  baseline: 0.2", "  basline: 0.2"));
  CAIRN_EXPECT_THROWS_WITH(OccupancyScenario::FromYaml(typo), std::invalid_argument, "Did you mean 'baseline'?");
  CAIRN_EXPECT_THROWS_WITH(OccupancyScenario::FromYaml("/no/such/scene.yaml"), std::invalid_argument,
                           "Cannot read '/no/such/scene.yaml'");
  const std::string broken = Write("broken.yaml", "camera: [1, 2\n");
  CAIRN_EXPECT_THROWS_WITH(OccupancyScenario::FromYaml(broken), std::invalid_argument, "Malformed YAML in", "line 2");
  CAIRN_EXPECT_THROWS_WITH(OccupancyScenario::LookAt(Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(0, 0, 2)),
                           std::invalid_argument, "straight up or down");
}

}  // namespace
}  // namespace cairn::perception
