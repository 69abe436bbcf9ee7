// Runs `cairn plan --whole-body` as a user would: trajectory.json and trajectory.png next to the plan.

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "../planning/support/shared_oracle.h"
#include "run_cairn.h"
#include "test_paths.h"

namespace {

using cairn::test::CairnRun;
using cairn::test::RunCairn;
using ::testing::HasSubstr;
namespace fs = std::filesystem;

TEST(PlanWholeBodyTest, WritesTheTrajectoryAndItsPictureIntoOut) {
  cairn::planning::test::SharedOracle(cairn::planning::WalkingObjective::kComWorkPlusHeat);
  const fs::path dir = fs::temp_directory_path() / ("cairn_plan_whole_body_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  const CairnRun run = RunCairn("plan --scenario " + std::string(CAIRN_SOURCE_DIR) +
                                "/examples/scenarios/high_bar.yaml --whole-body --time-limit 20 --oracle-cache " +
                                std::string(CAIRN_BINARY_DIR) + "/test-oracle-cache --out " + dir.string());
  std::ifstream file(dir / "trajectory.json");
  std::stringstream json;
  json << file.rdbuf();
  // Failures are results: the files are written either way, and the exit code says which it was.
  const bool found = json.str().find("{\"found\": true") == 0;
  EXPECT_EQ(run.exit_code, found ? 0 : 1) << run.output;
  EXPECT_THAT(run.output, HasSubstr(found ? "whole body solved: " : "whole body FAILED"));
  for (const char* key : {"\"report\": {", "\"coordinates\": [\"base_x\"", "\"label\": \"stance 0 start\"",
                          "\"contacts\": [\"l_sole\", \"r_sole\"]", "\"min_clearance\": ", "\"q\": ["}) {
    EXPECT_THAT(json.str(), HasSubstr(key));
  }
  ASSERT_TRUE(fs::exists(dir / "trajectory.png"));
  std::ifstream png(dir / "trajectory.png", std::ios::binary);
  char magic[4] = {};
  png.read(magic, 4);
  EXPECT_EQ(std::string(magic + 1, 3), "PNG");
  EXPECT_TRUE(fs::exists(dir / "plan.json"));
  fs::remove_all(dir);
}

}  // namespace
