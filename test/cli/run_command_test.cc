// Runs `cairn run` (the main diagram) and `cairn diagram --scenario` as a user would: the files exist and agree with
// each other, the steps name the true material under them, and bad input is one line. Whether the robot reaches
// the goal without a fall is asserted in test/planning/run, not here.

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "../planning/support/shared_oracle.h"
#include "run_cairn_streams.h"
#include "test_paths.h"

namespace {

namespace fs = std::filesystem;
using cairn::test::CairnStreams;
using cairn::test::RunCairnStreams;
using ::testing::HasSubstr;
using ::testing::StartsWith;

const std::string kCache = std::string(CAIRN_BINARY_DIR) + "/test-oracle-cache";
const std::string kMockup = std::string(CAIRN_SOURCE_DIR) + "/examples/scenarios/mockup/";

std::string Slurp(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

fs::path Folder(const std::string& name) {
  const fs::path dir = fs::path(CAIRN_BINARY_DIR) / "test-run" / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

// Width and height of a PNG, from its IHDR chunk.
std::pair<int, int> PngSize(const std::string& png) {
  auto be32 = [&](std::size_t at) {
    return (static_cast<unsigned char>(png[at]) << 24) | (static_cast<unsigned char>(png[at + 1]) << 16) |
           (static_cast<unsigned char>(png[at + 2]) << 8) | static_cast<unsigned char>(png[at + 3]);
  };
  return png.size() > 24 ? std::pair<int, int>(be32(16), be32(20)) : std::pair<int, int>(0, 0);
}

// The mock-up (wood and tiles), walked: run.json says what the camera reconstructed and what was walked on it,
// timing.json how long each stage took, and the perception, the perceived terrain and the walk are drawn.
TEST(RunCommandTest, WritesTheWalkAndThePerceivedTerrain) {
  cairn::planning::test::SharedOracle(cairn::planning::WalkingObjective::kComWorkPlusHeat);
  const fs::path out = Folder("mockup");
  const CairnStreams run = RunCairnStreams("run --scenario " + kMockup + "mockup.yaml --oracle-cache " +
                                           kCache + " --settle-time 0.3 --out " + out.string());
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_THAT(run.out, HasSubstr("run        mock-up, wood and tiles (objective ecom_heat, stabiliser fft)"));
  EXPECT_THAT(run.out, HasSubstr("perceived  terrain of 96 x 72 cells"));
  EXPECT_THAT(run.out, HasSubstr("/run.json, timing.json, perception.png, terrain.png, run.html, walk_zmp.png"));
  for (const char* name : {"run.json", "timing.json", "perception.png", "terrain.png", "run.html", "walk_zmp.png",
                           "walk_com.png", "walk_steps.png", "walk.html"}) {
    ASSERT_TRUE(fs::exists(out / name)) << name;
  }
  EXPECT_THAT(Slurp(out / "terrain.png"), StartsWith("\x89PNG"));
  const std::string report = Slurp(out / "perception.png");
  ASSERT_THAT(report, StartsWith("\x89PNG"));
  // Three 320-pixel camera panels side by side, the grid's panels under them.
  const auto [width, height] = PngSize(report);
  EXPECT_GE(width, 3 * 320);
  EXPECT_GE(height, 240 + 72 * 4);
  // The 3-D viewer shows the terrain as perceived, its occupied cells among it.
  const std::string viewer = Slurp(out / "run.html");
  EXPECT_THAT(viewer, HasSubstr("the terrain as perceived"));
  EXPECT_THAT(viewer, HasSubstr("\"name\": \"perceived ground\""));
  EXPECT_THAT(viewer, HasSubstr("\"name\": \"occupied\""));
  const nlohmann::json timing = nlohmann::json::parse(Slurp(out / "timing.json"));
  for (const char* stage : {"perception_s", "footsteps_s", "trajectory_s", "stabilizer_s", "plant_s"}) {
    EXPECT_GE(timing.at(stage).get<double>(), 0.0) << stage;
  }
  EXPECT_GT(timing.at("perception_s").get<double>(), 0.0);
  const nlohmann::json walk = nlohmann::json::parse(Slurp(out / "run.json"));
  EXPECT_FALSE(walk.contains("seconds"));  // wall times stay out of run.json, so equal runs write equal bytes
  // Whether the robot reaches the goal is asserted in test/planning/run; here, that the plan was walked.
  EXPECT_TRUE(walk.at("walked").get<bool>()) << walk.at("reason");
  const auto& perception = walk.at("perception");
  EXPECT_EQ(perception.at("cells").get<int>(), 96 * 72);
  // The camera sees the floor ahead of the robot, not the area behind it.
  EXPECT_GT(perception.at("ground_cells").get<int>(), 96 * 72 / 3);
  EXPECT_LT(perception.at("ground_cells").get<int>(), 96 * 72);
  EXPECT_GE(walk.at("steps").size(), 4u);
  for (const auto& step : walk.at("steps")) {
    EXPECT_THAT(step.at("material").get<std::string>(), ::testing::AnyOf("ceramic", "wood")) << step;
    EXPECT_LE(step.at("predicted_rcof").get<double>(), step.at("mu_allowed").get<double>() + 1e-6) << step;
  }
}

TEST(RunCommandTest, DiagramShowsTheMainDiagramOfAScenario) {
  cairn::planning::test::SharedOracle(cairn::planning::WalkingObjective::kComWorkPlusHeat);
  const CairnStreams run =
      RunCairnStreams("diagram --dot --scenario " + kMockup + "mockup.yaml --oracle-cache " + kCache);
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_THAT(run.out, HasSubstr("digraph \"main\""));
  for (const char* block : {"|camera|", "|stereo|", "|occupancy|", "|friction|", "|terrain_assembler|", "|footsteps|",
                            "|plant|"}) {
    EXPECT_THAT(run.out, HasSubstr(block));
  }
}

TEST(RunCommandTest, RefusesBadInputWithOneLine) {
  const fs::path dir = Folder("bad");
  const fs::path ice = dir / "ice.yaml";
  std::ofstream(ice) << R"(name: ice
terrain:
  min: [-0.5, -1.0]
  max: [1.5, 1.0]
  regions:
    - {name: ice, box: {min: [-0.5, -1.0], max: [1.5, 1.0]}, friction: 0.1}
start: {left: [0.0, 0.1, 0.0], right: [0.0, -0.1, 0.0]}
goal: {left: [0.4, 0.1, 0.0], right: [0.4, -0.1, 0.0]}
)";
  const CairnStreams run = RunCairnStreams("run --scenario " + ice.string() + " --oracle-cache " + kCache);
  EXPECT_EQ(run.exit_code, 1) << run.err;
  EXPECT_EQ(run.err_lines(), 1) << run.err;
  EXPECT_THAT(run.err, StartsWith("cairn run: "));
  EXPECT_THAT(run.err, HasSubstr("region 'ice' states a friction, not a material"));
  const CairnStreams usage = RunCairnStreams("run --scenario " + kMockup + "mockup.yaml --stabilizer lqr");
  EXPECT_EQ(usage.exit_code, 2) << usage.err;
  EXPECT_THAT(usage.err, HasSubstr("--stabilizer"));
  const CairnStreams diagram = RunCairnStreams("diagram --example pendulum --scenario " + ice.string());
  EXPECT_EQ(diagram.exit_code, 2) << diagram.err;
  EXPECT_THAT(diagram.err, HasSubstr("--scenario is for the walk and main diagrams"));
}

}  // namespace
