#include "command_registry.h"

namespace cairn::cli {

// Each subcommand is defined in its own <name>_command.cc; declare its registration function here and call it
// below, in the order `cairn --help` lists them.

void RegisterPendulumCommand(CommandRegistry* registry);
void RegisterDiagramCommand(CommandRegistry* registry);
void RegisterStereoEvalCommand(CommandRegistry* registry);
void RegisterOccupancyCommand(CommandRegistry* registry);
void RegisterModelInfoCommand(CommandRegistry* registry);
void RegisterFrictionCommand(CommandRegistry* registry);
void RegisterFrictionTrainCommand(CommandRegistry* registry);
void RegisterFrictionDatasetCommand(CommandRegistry* registry);
void RegisterPlanCommand(CommandRegistry* registry);
void RegisterSimulateCommand(CommandRegistry* registry);
void RegisterOracleCommand(CommandRegistry* registry);
void RegisterTraverseCommand(CommandRegistry* registry);
void RegisterAffordanceCommand(CommandRegistry* registry);
void RegisterWalkCommand(CommandRegistry* registry);

void RegisterAllCommands(CommandRegistry* registry) {
  RegisterPendulumCommand(registry);
  RegisterDiagramCommand(registry);
  RegisterStereoEvalCommand(registry);
  RegisterOccupancyCommand(registry);
  RegisterModelInfoCommand(registry);
  RegisterFrictionCommand(registry);
  RegisterFrictionTrainCommand(registry);
  RegisterFrictionDatasetCommand(registry);
  RegisterPlanCommand(registry);
  RegisterSimulateCommand(registry);
  RegisterOracleCommand(registry);
  RegisterTraverseCommand(registry);
  RegisterAffordanceCommand(registry);
  RegisterWalkCommand(registry);
}

}  // namespace cairn::cli
