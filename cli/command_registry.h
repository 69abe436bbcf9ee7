#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

namespace cairn::cli {

/// What a subcommand does once its flags are parsed; returns the process exit code (0 on success).
/// A failing command throws (std::exception); main() prints its message on one line and exits 1.
using CommandAction = std::function<int()>;

/// The `cairn` subcommands. Each subcommand registers a setup function that declares its flags on a CLI11
/// subcommand (binding them to state it owns) and returns the action to run when that subcommand is chosen.
class CommandRegistry {
 public:
  using Setup = std::function<CommandAction(CLI::App& subcommand)>;

  /// Adds subcommand `name`; throws std::logic_error if the name is taken.
  void Add(const std::string& name, const std::string& summary, Setup setup);

  /// Declares every registered subcommand on `app` and returns their actions, in registration order.
  struct Bound {
    CLI::App* subcommand;
    CommandAction action;
  };
  std::vector<Bound> BindTo(CLI::App& app) const;

  std::vector<std::string> names() const;

 private:
  struct Entry {
    std::string name;
    std::string summary;
    Setup setup;
  };
  std::vector<Entry> entries_;
};

/// Registers every subcommand Cairn ships (commands.cc lists them).
void RegisterAllCommands(CommandRegistry* registry);

}  // namespace cairn::cli
