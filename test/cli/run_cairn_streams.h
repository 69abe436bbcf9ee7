#pragma once

/// @file
/// Runs `cairn` with its standard output and standard error kept apart, for the tests of what each stream gets
/// (one-line errors, no progress bars in a redirected stderr, a full standard output).

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include "test_paths.h"

namespace cairn::test {

/// What one run of `cairn` wrote to each stream, and its exit code (-1 if it did not exit).
struct CairnStreams {
  int exit_code{-1};
  std::string out;
  std::string err;
  /// Lines written to stderr.
  int err_lines() const { return static_cast<int>(std::count(err.begin(), err.end(), '\n')); }
};

/// Runs `cairn <arguments>` through the shell. Standard output goes to `stdout_target` if given (e.g.
/// "/dev/full"), else it is captured; `shell_prefix` runs first in the same shell (e.g. "ulimit -f 4;").
inline CairnStreams RunCairnStreams(const std::string& arguments, const std::string& stdout_target = "",
                                    const std::string& shell_prefix = "") {
  namespace fs = std::filesystem;
  static int serial = 0;
  const fs::path base = fs::temp_directory_path() / ("cairn_streams_" + std::to_string(::getpid()) + "_" +
                                                     std::to_string(serial++));
  const std::string out_path = base.string() + ".out", err_path = base.string() + ".err";
  const std::string command = shell_prefix + " " + std::string(CAIRN_CLI_PATH) + " " + arguments + " >" +
                              (stdout_target.empty() ? out_path : stdout_target) + " 2>" + err_path;
  CairnStreams run;
  const int status = std::system(command.c_str());
  run.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  auto read = [](const std::string& path) {
    std::ifstream in(path);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
  };
  if (stdout_target.empty()) run.out = read(out_path);
  run.err = read(err_path);
  std::error_code ignored;
  fs::remove(out_path, ignored);
  fs::remove(err_path, ignored);
  return run;
}

}  // namespace cairn::test
