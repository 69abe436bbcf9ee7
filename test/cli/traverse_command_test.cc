// Runs `cairn traverse` as a user would.

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>

#include "run_cairn.h"
#include "test_paths.h"

namespace {

using cairn::test::RunCairn;
using ::testing::HasSubstr;
namespace fs = std::filesystem;

const std::string kScenario = std::string(CAIRN_SOURCE_DIR) + "/examples/scenarios/traverse/plants_and_water.yaml";

std::string Read(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

class TraverseCommandTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("cairn_traverse_cli_" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
};

TEST_F(TraverseCommandTest, WritesLayersAndSummary) {
  const fs::path out = dir_ / "run";
  const auto run = RunCairn("traverse --scenario " + kScenario + " --out " + out.string());
  ASSERT_EQ(run.exit_code, 0) << run.output;
  EXPECT_THAT(run.output, HasSubstr("'soft plants'"));
  EXPECT_THAT(run.output, HasSubstr("collapsible ground stepped on: no"));
  for (const char* name : {"elevation.png", "slope.png", "roughness.png", "semantics.png", "collapsibility.png",
                           "traversability.png"}) {
    const cv::Mat image = cv::imread((out / name).string());
    EXPECT_FALSE(image.empty()) << name;
    EXPECT_GT(image.cols, 100) << name;
  }
  const std::string summary = Read(out / "summary.json");
  EXPECT_THAT(summary, HasSubstr("\"reached_goal\": true"));
  EXPECT_THAT(summary, HasSubstr("\"stepped_on_collapsible\": false"));
  EXPECT_THAT(summary, HasSubstr("\"probes_made\": 3"));
  // The robot walked around the soft plants and the water: longer than the straight 8 m from start to goal, and
  // not absurdly so.
  const double walked = nlohmann::json::parse(summary).at("path_length_m").get<double>();
  EXPECT_GT(walked, 8.0);
  EXPECT_LT(walked, 16.0);
  // The folder is replaced as a whole; a foreign file in it is refused before anything is written.
  std::ofstream(out / "notes.txt") << "mine";
  const auto refused = RunCairn("traverse --scenario " + kScenario + " --out " + out.string());
  EXPECT_EQ(refused.exit_code, 1);
  EXPECT_THAT(refused.output, HasSubstr("notes.txt"));
  EXPECT_TRUE(fs::exists(out / "summary.json"));
}

TEST_F(TraverseCommandTest, NoProbingCrossesSoftSoilAndSaysSo) {
  const auto run = RunCairn("traverse --scenario " + kScenario + " --no-probing --json");
  ASSERT_EQ(run.exit_code, 0) << run.output;
  EXPECT_THAT(run.output, HasSubstr("\"probing\": false"));
  EXPECT_THAT(run.output, HasSubstr("\"stepped_on_collapsible\": true"));
  EXPECT_THAT(run.output, HasSubstr("\"soft plants\""));
}

TEST_F(TraverseCommandTest, BadScenarioIsOneLine) {
  const fs::path bad = dir_ / "bad.yaml";
  std::ofstream(bad) << "start: [1, 1]\ngoal: [1, 2]\nprobe: {reach: -1}\n";
  const auto run = RunCairn("traverse --scenario " + bad.string());
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_THAT(run.output, HasSubstr("line 3"));
  EXPECT_THAT(run.output, HasSubstr("'reach' must be in [0.05, 10]"));
  EXPECT_EQ(std::count(run.output.begin(), run.output.end(), '\n'), 1) << run.output;
}

}  // namespace
