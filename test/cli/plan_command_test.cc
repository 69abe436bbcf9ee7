// Runs `cairn plan` as a user would.

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "../planning/support/shared_oracle.h"
#include "run_cairn.h"

namespace {

using cairn::test::CairnRun;
using cairn::test::RunCairn;
using ::testing::HasSubstr;
namespace fs = std::filesystem;

const std::string kScenarios = std::string(CAIRN_SOURCE_DIR) + "/examples/scenarios/";
// The tests' shared oracle cache: SharedOracle() builds it once under a lock before the command reads it.
const std::string kCache = std::string(CAIRN_BINARY_DIR) + "/test-oracle-cache";

class PlanCommandTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("cairn_plan_cli_" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
};

TEST_F(PlanCommandTest, PlansAScenarioAndWritesJsonAndPicture) {
  cairn::planning::test::SharedOracle(cairn::planning::WalkingObjective::kComWorkPlusHeat);
  const CairnRun run = RunCairn("plan --scenario " + kScenarios + "flat.yaml --json --time-limit 20 --oracle-cache " +
                                kCache + " --out " + dir_.string());
  ASSERT_EQ(run.exit_code, 0) << run.output;
  for (const char* key : {"\"found\": true", "\"reason\": \"\"", "\"steps\": ", "\"energy_J\": ", "\"duration_s\": ",
                          "\"distance_m\": ", "\"max_rcof\": ", "\"min_friction_margin\": ", "\"epsilon\": ",
                          "\"expansions\": ", "\"plan_ms\": ", "\"footsteps\": [{\"side\": ", "\"t_ds\": ",
                          "\"t_sw\": ", "\"rcof\": ", "\"mu_allowed\": "}) {
    EXPECT_THAT(run.output, HasSubstr(key));
  }
  std::ifstream json(dir_ / "plan.json");
  std::stringstream contents;
  contents << json.rdbuf();
  EXPECT_THAT(run.output, HasSubstr(contents.str().substr(0, 200)));
  ASSERT_TRUE(fs::exists(dir_ / "plan.png"));
  EXPECT_GT(fs::file_size(dir_ / "plan.png"), 1000u);
}

TEST_F(PlanCommandTest, ReportsNoPlanAsAResult) {
  cairn::planning::test::SharedOracle(cairn::planning::WalkingObjective::kComWorkPlusHeat);
  const fs::path scenario = dir_ / "moat.yaml";
  std::ofstream(scenario) << R"(name: goal across a moat
terrain:
  min: [-0.5, -1.0]
  max: [3.0, 1.0]
  regions:
    - {name: near, box: {min: [-0.5, -1.0], max: [1.0, 1.0]}, friction: 1.0}
    - {name: far, box: {min: [2.0, -1.0], max: [3.0, 1.0]}, friction: 1.0}
start: {left: [0.0, 0.1, 0], right: [0.0, -0.1, 0]}
goal: {left: [2.5, 0.1, 0], right: [2.5, -0.1, 0]}
)";
  const CairnRun run = RunCairn("plan --scenario " + scenario.string() + " --oracle-cache " + kCache);
  EXPECT_EQ(run.exit_code, 0) << run.output;
  EXPECT_THAT(run.output, HasSubstr("no plan"));
  EXPECT_THAT(run.output, HasSubstr("the goal is unreachable"));
}

TEST_F(PlanCommandTest, RejectsBadInputClearly) {
  const fs::path scenario = dir_ / "typo.yaml";
  std::ofstream(scenario) << "name: typo\nterain: {}\n";
  CairnRun run = RunCairn("plan --scenario " + scenario.string());
  EXPECT_EQ(run.exit_code, 1) << run.output;
  EXPECT_THAT(run.output, HasSubstr("line 2"));
  EXPECT_THAT(run.output, HasSubstr("unknown key 'terain'"));
  EXPECT_THAT(run.output, HasSubstr("Did you mean 'terrain'?"));
  run = RunCairn("plan --scenario " + kScenarios + "flat.yaml --objective energy");
  EXPECT_EQ(run.exit_code, 2) << run.output;
  EXPECT_THAT(run.output, HasSubstr("energy"));
  run = RunCairn("plan --scenario /nonexistent.yaml");
  EXPECT_EQ(run.exit_code, 1) << run.output;
  EXPECT_THAT(run.output, HasSubstr("Cannot read '/nonexistent.yaml'"));
  run = RunCairn("plan --scenario " + kScenarios + "flat.yaml --time-limit -3");
  EXPECT_EQ(run.exit_code, 2) << run.output;
}

}  // namespace
