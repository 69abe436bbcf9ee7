// Runs the `cairn` program as a user would and checks exit codes and output.

#include <algorithm>
#include <array>
#include <cstdio>
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "run_cairn.h"

#include "cairn/version.h"
#include "test_paths.h"

namespace {

using cairn::test::CairnRun;
using cairn::test::RunCairn;

using ::testing::HasSubstr;

TEST(CairnCommandTest, VersionAndHelp) {
  const CairnRun version = RunCairn("--version");
  EXPECT_EQ(version.exit_code, 0);
  EXPECT_THAT(version.output, HasSubstr("cairn " CAIRN_VERSION_STRING));
  // A cairn run from the build tree takes its data from the source tree (the install test checks the prefix's).
  EXPECT_THAT(version.output, HasSubstr(std::string("data ") + CAIRN_SOURCE_DIR + "/data"));
  const CairnRun help = RunCairn("--help");
  EXPECT_EQ(help.exit_code, 0);
  EXPECT_THAT(help.output, HasSubstr("pendulum"));
  EXPECT_THAT(help.output, HasSubstr("diagram"));
}

TEST(CairnCommandTest, UsageErrorsExitWithTwoAndPrintUsage) {
  const CairnRun none = RunCairn("");
  EXPECT_EQ(none.exit_code, 2);
  EXPECT_THAT(none.output, HasSubstr("Usage:"));
  const CairnRun unknown = RunCairn("pendlum");
  EXPECT_EQ(unknown.exit_code, 2);
  EXPECT_THAT(unknown.output, HasSubstr("unknown subcommand 'pendlum'; did you mean 'pendulum'?"));
  const CairnRun bad_flag = RunCairn("pendulum --bogus");
  EXPECT_EQ(bad_flag.exit_code, 2);
  EXPECT_THAT(bad_flag.output, HasSubstr("--bogus"));
  const CairnRun bad_value = RunCairn("pendulum --integrator leapfrog");
  EXPECT_EQ(bad_value.exit_code, 2);
  EXPECT_THAT(bad_value.output, HasSubstr("leapfrog"));
}

TEST(CairnCommandTest, FailingCommandExitsWithOneAndAOneLineReason) {
  const CairnRun run = RunCairn("pendulum --duration 0.01 --csv /nonexistent_cairn_dir/log.csv");
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_THAT(run.output, HasSubstr("cairn pendulum: error: --csv '/nonexistent_cairn_dir/log.csv' cannot be written: "
                                    "its folder '/nonexistent_cairn_dir' does not exist"));
  EXPECT_EQ(std::count(run.output.begin(), run.output.end(), '\n'), 1) << run.output;
}

TEST(CairnCommandTest, PendulumReportsTheSimulation) {
  const CairnRun run = RunCairn("pendulum --duration 2 --json");
  EXPECT_EQ(run.exit_code, 0) << run.output;
  EXPECT_THAT(run.output, HasSubstr("\"time\": 2.000000"));
  EXPECT_THAT(run.output, HasSubstr("\"steps\": 2000"));
}

TEST(CairnCommandTest, DiagramPrintsGraphviz) {
  const CairnRun run = RunCairn("diagram --dot");
  EXPECT_EQ(run.exit_code, 0);
  EXPECT_THAT(run.output, HasSubstr("digraph \"pendulum\""));
  EXPECT_THAT(run.output, HasSubstr("|controller|"));
  const CairnRun text = RunCairn("diagram");
  EXPECT_THAT(text.output, HasSubstr("plant.state -> hold.u"));
}

}  // namespace
