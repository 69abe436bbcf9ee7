#pragma once

/// @file
/// Runs the `cairn` program (path in CAIRN_CLI_PATH) as a user would, for the command-line tests.

#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <string>
#include "test_paths.h"

namespace cairn::test {

/// What one run of `cairn` printed (stdout and stderr together) and its exit code (-1 if it did not exit).
struct CairnRun {
  int exit_code{-1};
  std::string output;
};

/// Runs `cairn <arguments>` through the shell.
inline CairnRun RunCairn(const std::string& arguments) {
  const std::string command = std::string(CAIRN_CLI_PATH) + " " + arguments + " 2>&1";
  CairnRun run;
  FILE* pipe = ::popen(command.c_str(), "r");
  if (pipe == nullptr) return run;
  std::array<char, 4096> buffer{};
  while (std::fgets(buffer.data(), buffer.size(), pipe) != nullptr) run.output += buffer.data();
  const int status = ::pclose(pipe);
  run.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return run;
}

}  // namespace cairn::test
