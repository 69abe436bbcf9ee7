#include "command_registry.h"

namespace cairn::cli {

// Each subcommand is defined in its own <name>_command.cc; declare its registration function here and call it
// below, in the order `cairn --help` lists them.

void RegisterPendulumCommand(CommandRegistry* registry);
void RegisterDiagramCommand(CommandRegistry* registry);

void RegisterAllCommands(CommandRegistry* registry) {
  RegisterPendulumCommand(registry);
  RegisterDiagramCommand(registry);
  (void)registry;
}

}  // namespace cairn::cli
