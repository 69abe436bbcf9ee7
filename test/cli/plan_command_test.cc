// Runs `cairn plan` as a user would.

#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <utility>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cairn/planning/locomotion/transition_oracle.h>

#include "../planning/support/shared_oracle.h"
#include "run_cairn.h"
#include "run_cairn_streams.h"
#include "test_paths.h"

namespace {

using cairn::test::CairnRun;
using cairn::test::CairnStreams;
using cairn::test::RunCairn;
using cairn::test::RunCairnStreams;
using ::testing::Not;
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

  // A scenario for a copy of the humanoid whose reach is cut to a few centimetres: its oracle has 288 entries
  // and builds in about a second, so tests can build it afresh. No step reaches the goal, 0.5 m ahead.
  fs::path TinyRobotScenario() {
    std::ifstream in(std::string(CAIRN_SOURCE_DIR) + "/data/robots/cairn_humanoid_walking.yaml");
    std::stringstream text;
    text << in.rdbuf();
    std::string robot = text.str();
    for (const auto& [from, to] : {std::pair<std::string, std::string>{"urdf: cairn_humanoid.urdf",
                                                                       "urdf: " + std::string(CAIRN_SOURCE_DIR) +
                                                                           "/data/robots/cairn_humanoid.urdf #"},
                                   {"dx: [0.0, 0.38]", "dx: [0.0, 0.1]"},
                                   {"dy: [0.17, 0.30]", "dy: [0.17, 0.2]"},
                                   {"dz: [-0.15, 0.15]", "dz: [0.0, 0.05]"},
                                   {"dtheta_deg: [0.0, 30.0]", "dtheta_deg: [0.0, 15.0]"}}) {
      const auto at = robot.find(from);
      EXPECT_NE(at, std::string::npos) << from;
      if (at != std::string::npos) robot.replace(at, from.size(), to);
    }
    std::ofstream(dir_ / "tiny_robot.yaml") << robot;
    const fs::path scenario = dir_ / "tiny.yaml";
    std::ofstream(scenario) << "name: tiny\nrobot: " << (dir_ / "tiny_robot.yaml").string() << R"(
terrain:
  min: [-0.5, -1.0]
  max: [1.0, 1.0]
  regions:
    - {name: floor, box: {min: [-0.5, -1.0], max: [1.0, 1.0]}, friction: 1.0}
start: {left: [0.0, 0.1, 0], right: [0.0, -0.1, 0]}
goal: {left: [0.5, 0.1, 0], right: [0.5, -0.1, 0], tolerance: 0.05}
planner: {time_limit: 5, max_expansions: 2000}
)";
    return scenario;
  }
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
  // plan.json is the printed plan without its wall-clock times (so that it is the same on every run).
  EXPECT_THAT(contents.str(), Not(HasSubstr("_ms\"")));
  std::string printed = run.output;
  for (const std::string key : {"\"plan_ms\": ", "\"first_plan_ms\": ", "\"refine_ms\": "}) {
    const std::size_t at = printed.find(key);
    ASSERT_NE(at, std::string::npos) << key << " missing from the printed plan";
    printed.erase(at, printed.find(", ", at) + 2 - at);  // the key, its value and the separator
  }
  EXPECT_THAT(printed, HasSubstr(contents.str().substr(0, contents.str().size() - 1)));
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
  EXPECT_THAT(run.output, HasSubstr("--scenario '/nonexistent.yaml' does not exist"));
  run = RunCairn("plan --scenario " + kScenarios + "flat.yaml --time-limit -3");
  EXPECT_EQ(run.exit_code, 2) << run.output;
}

TEST_F(PlanCommandTest, AnUnwritableOutFailsBeforeTheOracleAndTheSearch) {
  std::ofstream(dir_ / "a_file") << "x";
  const fs::path cache = dir_ / "fresh-cache";
  // With a time limit of ten minutes: it used to plan for all of it and then fail without printing the plan.
  const std::string out = (dir_ / "a_file" / "plan").string();
  const CairnStreams run = RunCairnStreams("plan --scenario " + kScenarios + "flat.yaml --time-limit 600 " +
                                           "--oracle-cache " + cache.string() + " --out " + out);
  EXPECT_EQ(run.exit_code, 1) << run.err;
  EXPECT_EQ(run.err_lines(), 1) << run.err;
  EXPECT_THAT(run.err, HasSubstr("cairn plan: error: Cannot write the folder '" + out + "'"));
  EXPECT_THAT(run.err, Not(HasSubstr("oracle")));
  EXPECT_FALSE(fs::exists(cache)) << "the oracle was not even looked for";
  // A folder holding files plan does not write is refused the same way, and kept.
  fs::create_directories(dir_ / "results");
  std::ofstream(dir_ / "results" / "notes.txt") << "mine";
  const CairnStreams kept = RunCairnStreams("plan --scenario " + kScenarios + "flat.yaml --oracle-cache " +
                                            cache.string() + " --out " + (dir_ / "results").string());
  EXPECT_EQ(kept.exit_code, 1);
  EXPECT_THAT(kept.err, HasSubstr("it holds 'notes.txt', which this command does not write"));
  EXPECT_TRUE(fs::exists(dir_ / "results" / "notes.txt"));
}

TEST_F(PlanCommandTest, ProgressIsTwoLinesWhenStderrIsNotATerminal) {
  const fs::path scenario = TinyRobotScenario();
  const fs::path cache = dir_ / "cache";
  const std::string plan = "plan --scenario " + scenario.string() + " --oracle-cache " + cache.string();
  const CairnStreams built = RunCairnStreams(plan);
  ASSERT_EQ(built.exit_code, 0) << built.err;
  // The bar used to redraw itself a hundred times (7.7 KB of carriage returns for the humanoid's oracle).
  EXPECT_EQ(built.err.find('\r'), std::string::npos) << built.err;
  EXPECT_THAT(built.err, HasSubstr("Building transition oracle"));
  EXPECT_THAT(built.err, HasSubstr("building the transition oracle: started, 288 to do\n"));
  EXPECT_THAT(built.err, HasSubstr("building the transition oracle: done, 288 of 288\n"));
  EXPECT_EQ(built.err_lines(), 3) << built.err;
  const CairnStreams loaded = RunCairnStreams(plan);
  ASSERT_EQ(loaded.exit_code, 0) << loaded.err;
  EXPECT_THAT(loaded.err, HasSubstr("Loaded transition oracle"));
  EXPECT_EQ(loaded.err_lines(), 1) << loaded.err;
}

TEST_F(PlanCommandTest, AnUnusableOracleCacheWarnsAndPlansWithTheOracleInMemory) {
  const fs::path scenario = TinyRobotScenario();
  std::ofstream(dir_ / "a_file") << "x";
  const std::string cache = (dir_ / "a_file" / "cache").string();
  const CairnStreams run =
      RunCairnStreams("plan --scenario " + scenario.string() + " --oracle-cache " + cache + " --json");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  // One mechanism, the library's (TransitionOracle::LoadOrBuild): it names the folder and keeps the table.
  EXPECT_THAT(run.err, HasSubstr("Warning: the transition oracle is not cached: cannot create the folder '" + cache +
                                 "'"));
  EXPECT_THAT(run.err, HasSubstr("continuing with the table in memory"));
  EXPECT_THAT(run.out, HasSubstr("\"scenario\": \"tiny\""));
}

TEST_F(PlanCommandTest, ATimeLimitReachedWhileRasterisingIsANoPlanResult) {
  // A million cells and a nanosecond: the time runs out at the first row, before any oracle is looked for.
  const fs::path scenario = dir_ / "large.yaml";
  std::ofstream(scenario) << R"(name: large floor
terrain:
  min: [-5, -5]
  max: [5, 5]
  resolution: 0.01
  regions:
    - {name: floor, box: {min: [-5, -5], max: [5, 5]}, friction: 1.0}
start: {left: [0.0, 0.1, 0], right: [0.0, -0.1, 0]}
goal: {left: [2.0, 0.1, 0], right: [2.0, -0.1, 0]}
)";
  const fs::path cache = dir_ / "cache";
  const std::string plan = "plan --scenario " + scenario.string() + " --time-limit 1e-9 --oracle-cache " +
                           cache.string();
  const CairnStreams text = RunCairnStreams(plan);
  ASSERT_EQ(text.exit_code, 0) << text.err;
  EXPECT_THAT(text.out, HasSubstr("no plan    no plan within the time limit of 1e-09 s: the time limit ran out "
                                  "while rasterising the terrain of '" + scenario.string() + "' (region 1 of 1, "
                                  "1000 x 1000 cells); raise the limit"));
  const fs::path out = dir_ / "out";
  const CairnStreams json = RunCairnStreams(plan + " --json --out " + out.string());
  ASSERT_EQ(json.exit_code, 0) << json.err;
  EXPECT_THAT(json.out, HasSubstr("\"found\": false, \"reason\": \"no plan within the time limit"));
  EXPECT_THAT(json.out, HasSubstr("\"steps\": 0"));
  EXPECT_TRUE(fs::exists(out / "plan.json"));
  EXPECT_FALSE(fs::exists(out / "plan.png")) << "there is no terrain to draw";
  EXPECT_FALSE(fs::exists(cache)) << "the oracle was not needed";
  EXPECT_EQ(json.err, "");
}

TEST_F(PlanCommandTest, AScenarioFileLargerThanTwoMebibytesIsRefusedBeforeParsing) {
  // yaml-cpp took 3 s and 590 MB for 4 MB of obstacles before the loader could count them.
  const fs::path scenario = dir_ / "padded.yaml";
  std::ofstream(scenario) << "name: padded\n# " << std::string(2u << 20, 'x') << "\n";
  const CairnStreams run = RunCairnStreams("plan --scenario " + scenario.string());
  EXPECT_EQ(run.exit_code, 1) << run.err;
  EXPECT_EQ(run.err, "cairn plan: error: Cannot read '" + scenario.string() + "': it has 2097168 bytes, more than "
                     "the 2097152 a file of its kind may have.\n");
}

TEST_F(PlanCommandTest, JsonWithoutAPlanHasNullsNotPlaceholders) {
  const fs::path scenario = TinyRobotScenario();
  const CairnStreams run = RunCairnStreams("plan --scenario " + scenario.string() + " --oracle-cache " +
                                           (dir_ / "cache").string() + " --json");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_THAT(run.out, HasSubstr("\"found\": false"));
  // "first_plan_ms" was -1000 (the -1 s placeholder), cost and energy 0.
  for (const char* key : {"\"first_plan_ms\": null", "\"cost\": null", "\"energy_J\": null", "\"epsilon\": null",
                          "\"max_rcof\": null"}) {
    EXPECT_THAT(run.out, HasSubstr(key));
  }
  for (const char* bad : {": -1000", ": nan", ": -nan", ": inf", ": -inf"}) EXPECT_THAT(run.out, Not(HasSubstr(bad)));
}

// `cairn oracle build --source plant --cache` writes the table `cairn plan --oracle-source plant` loads from that
// cache (one cell, the default timings: six gaits walked in the plant), and the plan names its source. A table of
// another grid than the default is cached under its grid's fingerprint, so it never replaces the default table.
TEST_F(PlanCommandTest, PlansWithThePlantOracleTheOracleCommandBuilt) {
  const std::string cache = (dir_ / "cache").string();
  const std::string grid = (dir_ / "grid.yaml").string();
  std::ofstream(grid) << "dx: [0.1]\ndy: [0.2]\ndz: [0.0]\ndtheta: [0.0]\nmu: [1.0]\n";
  const std::string table = cache + "/cairn_humanoid-ecom_heat-plant-grid-" +
                            cairn::planning::OracleGrid::Load(grid).Fingerprint() + ".oracle";
  const CairnStreams built =
      RunCairnStreams("oracle build --source plant --grid " + grid + " --cache " + cache + " --json");
  ASSERT_EQ(built.exit_code, 0) << built.err;
  EXPECT_THAT(built.out, HasSubstr("\"out\": \"" + table + "\""));
  EXPECT_TRUE(fs::exists(table));
  EXPECT_FALSE(fs::exists(cache + "/cairn_humanoid-ecom_heat-plant.oracle"));
  const CairnStreams run = RunCairnStreams("plan --scenario " + kScenarios + "flat.yaml --json --time-limit 5 " +
                                           "--oracle-source plant --oracle-grid " + grid + " --oracle-cache " + cache);
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_THAT(run.err, HasSubstr("Loaded transition oracle"));
  EXPECT_THAT(run.err, Not(HasSubstr("Building")));
  EXPECT_THAT(run.out, HasSubstr("\"oracle_source\": \"plant t_ds "));
  EXPECT_THAT(run.out, HasSubstr(" steps 6 transient 2 friction 1 "));
  const CairnStreams bad = RunCairnStreams("plan --scenario " + kScenarios + "flat.yaml --oracle-source plants");
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_THAT(bad.err, HasSubstr("--oracle-source 'plants' is not one of 'model', 'plant', 'pipeline'"));
}

// A scenario that names the pipeline source (the whole-body torque cost of each gait, optimised and stabilised but
// not walked) gets its table built into the cache by `plan` itself on first use, and the plan names it.
TEST_F(PlanCommandTest, PlansWithThePipelineOracleOnTheWholeBodyTorqueCost) {
  const std::string cache = (dir_ / "cache").string();
  const std::string grid = (dir_ / "grid.yaml").string();
  std::ofstream(grid) << "dx: [0.1]\ndy: [0.2]\ndz: [0.0]\ndtheta: [0.0]\nmu: [1.0]\n";
  const std::string scenario = (dir_ / "pipeline.yaml").string();
  std::string text;
  {
    std::ifstream flat(kScenarios + "flat.yaml");
    text.assign(std::istreambuf_iterator<char>(flat), std::istreambuf_iterator<char>());
  }
  const std::string objective_line = "objective: ecom_heat\n";
  ASSERT_NE(text.find(objective_line), std::string::npos);
  std::ofstream(scenario) << std::string(text).replace(text.find(objective_line), objective_line.size(),
                                                        "objective: torque\noracle: pipeline\n");
  const CairnStreams run = RunCairnStreams("plan --scenario " + scenario + " --json --time-limit 5 --oracle-grid " +
                                           grid + " --oracle-cache " + cache);
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_THAT(run.out, HasSubstr("\"oracle_source\": \"pipeline t_ds "));
  EXPECT_THAT(run.out, HasSubstr(" stabilizer fft margin 0"));
  EXPECT_TRUE(fs::exists(cache + "/cairn_humanoid-torque-pipeline-grid-" +
                         cairn::planning::OracleGrid::Load(grid).Fingerprint() + ".oracle"));
  const CairnStreams heat = RunCairnStreams("plan --scenario " + kScenarios + "flat.yaml --oracle-source pipeline " +
                                            "--oracle-grid " + grid + " --oracle-cache " + cache);
  EXPECT_EQ(heat.exit_code, 1);
  EXPECT_THAT(heat.err, HasSubstr("measures no heat (objective 'ecom_heat'); use torque, ecom or time"));

  std::ofstream(scenario) << std::string(text).replace(text.find(objective_line), objective_line.size(),
                                                        "oracle: plants\n");
  const CairnStreams bad = RunCairnStreams("plan --scenario " + scenario);
  EXPECT_EQ(bad.exit_code, 1);
  EXPECT_THAT(bad.err, HasSubstr("oracle 'plants' is not one of model, plant, pipeline"));
  EXPECT_THAT(bad.err, HasSubstr(scenario));
  EXPECT_EQ(bad.err_lines(), 1) << bad.err;
}

}  // namespace
