// Runs the `cairn` program as a user would and checks exit codes and output.

#include <sys/wait.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "cairn/version.h"

namespace {

using ::testing::HasSubstr;

struct CommandRun {
  int exit_code;
  std::string output;  // stdout and stderr together
};

CommandRun RunCairn(const std::string& arguments) {
  const std::string command = std::string(CAIRN_CLI_PATH) + " " + arguments + " 2>&1";
  FILE* pipe = ::popen(command.c_str(), "r");
  EXPECT_NE(pipe, nullptr);
  CommandRun run{-1, ""};
  std::array<char, 4096> buffer{};
  while (std::fgets(buffer.data(), buffer.size(), pipe) != nullptr) run.output += buffer.data();
  const int status = ::pclose(pipe);
  run.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return run;
}

TEST(CairnCommandTest, VersionAndHelp) {
  const CommandRun version = RunCairn("--version");
  EXPECT_EQ(version.exit_code, 0);
  EXPECT_THAT(version.output, HasSubstr("cairn " CAIRN_VERSION_STRING));
  const CommandRun help = RunCairn("--help");
  EXPECT_EQ(help.exit_code, 0);
  EXPECT_THAT(help.output, HasSubstr("pendulum"));
  EXPECT_THAT(help.output, HasSubstr("diagram"));
}

TEST(CairnCommandTest, UsageErrorsExitWithTwoAndPrintUsage) {
  const CommandRun none = RunCairn("");
  EXPECT_EQ(none.exit_code, 2);
  EXPECT_THAT(none.output, HasSubstr("Usage:"));
  const CommandRun unknown = RunCairn("pendlum");
  EXPECT_EQ(unknown.exit_code, 2);
  EXPECT_THAT(unknown.output, HasSubstr("unknown subcommand 'pendlum'; did you mean 'pendulum'?"));
  const CommandRun bad_flag = RunCairn("pendulum --bogus");
  EXPECT_EQ(bad_flag.exit_code, 2);
  EXPECT_THAT(bad_flag.output, HasSubstr("--bogus"));
  const CommandRun bad_value = RunCairn("pendulum --integrator leapfrog");
  EXPECT_EQ(bad_value.exit_code, 2);
  EXPECT_THAT(bad_value.output, HasSubstr("leapfrog"));
}

TEST(CairnCommandTest, FailingCommandExitsWithOneAndAOneLineReason) {
  const CommandRun run = RunCairn("pendulum --duration 0.01 --csv /nonexistent_cairn_dir/log.csv");
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_THAT(run.output, HasSubstr("cairn pendulum: error: Cannot write '/nonexistent_cairn_dir/log.csv'"));
  EXPECT_EQ(std::count(run.output.begin(), run.output.end(), '\n'), 1) << run.output;
}

TEST(CairnCommandTest, PendulumReportsTheSimulation) {
  const CommandRun run = RunCairn("pendulum --duration 2 --json");
  EXPECT_EQ(run.exit_code, 0) << run.output;
  EXPECT_THAT(run.output, HasSubstr("\"time\": 2.000000"));
  EXPECT_THAT(run.output, HasSubstr("\"steps\": 2000"));
}

TEST(CairnCommandTest, DiagramPrintsGraphviz) {
  const CommandRun run = RunCairn("diagram --dot");
  EXPECT_EQ(run.exit_code, 0);
  EXPECT_THAT(run.output, HasSubstr("digraph \"pendulum\""));
  EXPECT_THAT(run.output, HasSubstr("|controller|"));
  const CommandRun text = RunCairn("diagram");
  EXPECT_THAT(text.output, HasSubstr("plant.state -> hold.u"));
}

}  // namespace
