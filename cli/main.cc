// The `cairn` command-line program: a thin dispatcher over the subcommands in CommandRegistry.
//
// Exit codes: 0 success; 1 a command failed (one-line reason on stderr); 2 bad usage (unknown subcommand or flag,
// usage printed on stderr).

#include <algorithm>
#include <exception>
#include <iostream>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "cairn/common/text_suggestions.h"
#include "cairn/version.h"
#include "command_registry.h"

int main(int argc, char** argv) {
  cairn::cli::CommandRegistry registry;
  cairn::cli::RegisterAllCommands(&registry);

  CLI::App app{"Cairn: perception-driven legged locomotion as block diagrams of typed systems.", "cairn"};
  app.set_version_flag("--version", "cairn " CAIRN_VERSION_STRING);
  app.require_subcommand(1);
  const auto bound = registry.BindTo(app);

  // CLI11 reports a mistyped subcommand as a missing one; name it and suggest the closest instead.
  if (argc > 1 && argv[1][0] != '-') {
    const std::vector<std::string> names = registry.names();
    if (std::find(names.begin(), names.end(), argv[1]) == names.end()) {
      std::cerr << "cairn: unknown subcommand '" << argv[1] << "'; did you mean "
                << cairn::QuotedList(cairn::ClosestNames(argv[1], names, 1)) << "?\n\n"
                << app.help();
      return 2;
    }
  }

  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& help) {
    return app.exit(help);
  } catch (const CLI::CallForAllHelp& help) {
    return app.exit(help);
  } catch (const CLI::CallForVersion& version) {
    return app.exit(version);
  } catch (const CLI::ParseError& error) {
    // CLI11 has its own exit codes; Cairn promises 2 for every usage error, with the usage printed.
    std::cerr << "cairn: " << error.what() << "\n\n";
    const CLI::App* failed = &app;
    for (const auto& b : bound) {
      if (b.subcommand->parsed()) failed = b.subcommand;
    }
    std::cerr << failed->help();
    return 2;
  }

  for (const auto& b : bound) {
    if (!b.subcommand->parsed()) continue;
    try {
      return b.action();
    } catch (const std::exception& error) {
      std::cerr << "cairn " << b.subcommand->get_name() << ": error: " << error.what() << "\n";
      return 1;
    }
  }
  return 2;  // Unreachable: require_subcommand(1) makes parse() throw when no subcommand is given.
}
