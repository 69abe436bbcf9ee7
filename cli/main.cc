// The `cairn` command-line program: a thin dispatcher over the subcommands in CommandRegistry.
//
// Exit codes (README, "The `cairn` command"):
//   0  success;
//   1  a command failed: a file is missing or malformed, a library refused the data, an output cannot be
//      written (including standard output, e.g. a full disk): one line "cairn <subcommand>: error: <reason>"
//      on stderr;
//   2  bad usage: an unknown subcommand or option, a missing or repeated option, a value that is not a number
//      or outside its option's stated range, options that contradict each other: one line
//      "cairn[ <subcommand>]: <reason> (see 'cairn[ <subcommand>] --help')" on stderr. `cairn` alone prints
//      the usage on stderr and exits with 2 too.

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <exception>
#include <iostream>
#include <new>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <opencv2/core.hpp>
#include <opencv2/core/utils/logger.hpp>

#include "cairn/common/text_suggestions.h"
#include "cairn/version.h"
#include "command_registry.h"
#include "data_directory.h"
#include "usage_error.h"
#include "usage_message.h"

namespace {

// A message as one line: line breaks inside it (some libraries' messages have them) become "; ".
std::string OneLine(std::string text) {
  while (!text.empty() && (text.back() == '\n' || text.back() == '\r' || text.back() == ' ')) text.pop_back();
  std::string line;
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] == '\n' || text[i] == '\r') {
      while (i + 1 < text.size() && (text[i + 1] == '\n' || text[i + 1] == '\r' || text[i + 1] == ' ')) ++i;
      line += "; ";
    } else {
      line += text[i];
    }
  }
  return line;
}

int UsageFailure(const std::string& program, const std::string& message) {
  std::cerr << program << ": " << OneLine(message) << " (see '" << program << " --help')\n";
  return 2;
}

int CommandFailure(const std::string& program, const std::string& message) {
  std::cerr << program << ": error: " << OneLine(message) << "\n";
  return 1;
}

// Output lost on a full disk or a closed pipe must not look like success: flush standard output and check it.
int FinishOutput(const std::string& program, int code) {
  errno = 0;
  std::cout.flush();
  const bool flushed = std::fflush(stdout) == 0;
  const int error = errno;
  if (!flushed || std::ferror(stdout) || !std::cout) {
    return CommandFailure(program, std::string("cannot write to standard output (") +
                                       (error != 0 ? std::strerror(error) : "write error") + "); the output is lost");
  }
  return code;
}

}  // namespace

int main(int argc, char** argv) {
  // OpenCV's own warnings ("[ WARN:0@0.003] global loadsave.cpp ...") would precede Cairn's one-line messages.
  cv::utils::logging::setLogLevel(cv::utils::logging::LOG_LEVEL_SILENT);

  cairn::cli::CommandRegistry registry;
  cairn::cli::RegisterAllCommands(&registry);

  CLI::App app{"Cairn: perception-driven legged locomotion as block diagrams of typed systems.", "cairn"};
  app.set_version_flag("--version", "cairn " CAIRN_VERSION_STRING "\ndata " + cairn::cli::DataDirectory());
  app.require_subcommand(1);
  const auto bound = registry.BindTo(app);
  const std::vector<std::string> names = registry.names();

  if (argc < 2) {
    std::cerr << app.help();
    return 2;
  }
  // CLI11 reports a mistyped subcommand, or an option before any subcommand, as a missing subcommand; say what
  // is wrong instead.
  const std::string first = argv[1];
  if (first.empty() || first[0] != '-') {
    if (std::find(names.begin(), names.end(), first) == names.end()) {
      const std::vector<std::string> closest = cairn::ClosestNames(first, names, 1);
      const bool close = !closest.empty() && cairn::EditDistance(first, closest.front()) <=
                                                  std::max<int>(2, static_cast<int>(first.size()) / 3);
      return UsageFailure("cairn", "unknown subcommand '" + first + "'; " +
                                       (close ? "did you mean '" + closest.front() + "'?"
                                              : "the subcommands are " + cairn::QuotedList(names)));
    }
  } else if (first != "-h" && first != "--help" && first != "--version") {
    return UsageFailure("cairn", "unknown option '" + first + "'; cairn takes a subcommand first (one of " +
                                     cairn::QuotedList(names) + "), then its options");
  }

  auto chosen = [&]() -> const cairn::cli::CommandRegistry::Bound* {
    for (const auto& b : bound) {
      if (b.subcommand->parsed()) return &b;
    }
    return nullptr;
  };
  auto program = [&]() {
    const auto* b = chosen();
    return b == nullptr ? std::string("cairn") : "cairn " + b->subcommand->get_name();
  };

  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& help) {
    return FinishOutput(program(), app.exit(help));
  } catch (const CLI::CallForAllHelp& help) {
    return FinishOutput(program(), app.exit(help));
  } catch (const CLI::CallForVersion& version) {
    return FinishOutput(program(), app.exit(version));
  } catch (const CLI::ParseError& error) {
    const auto* b = chosen();
    return UsageFailure(program(), cairn::cli::UsageMessage(error, b == nullptr ? app : *b->subcommand));
  } catch (const cairn::cli::UsageError& error) {  // thrown by the option declarations' checks
    return UsageFailure(program(), error.what());
  }

  const auto* b = chosen();
  if (b == nullptr) return UsageFailure("cairn", "a subcommand is required");  // require_subcommand(1) prevents it
  int code = 1;
  try {
    code = b->action();
  } catch (const cairn::cli::UsageError& error) {
    return UsageFailure(program(), error.what());
  } catch (const std::bad_alloc&) {
    return CommandFailure(program(), "out of memory; try smaller inputs");
  } catch (const cv::Exception& error) {
    // Not OpenCV's multi-line text with its source paths: what failed and where.
    return CommandFailure(program(), "OpenCV failed in " + error.func + ": " + error.err);
  } catch (const std::exception& error) {
    return CommandFailure(program(), error.what());
  } catch (...) {
    return CommandFailure(program(), "an unexpected error occurred");
  }
  return FinishOutput(program(), code);
}
