// `cairn diagram`: shows the example diagram's structure, as text or as Graphviz dot.

#include <iostream>
#include <memory>

#include "command_registry.h"
#include "examples/systems/pendulum_example.h"

namespace cairn::cli {

void RegisterDiagramCommand(CommandRegistry* registry) {
  registry->Add("diagram", "Print the example diagram (systems and connections, or Graphviz with --dot)",
                [](CLI::App& app) -> CommandAction {
                  auto dot = std::make_shared<bool>(false);
                  app.add_flag("--dot", *dot, "Print Graphviz dot (render with: cairn diagram --dot | dot -Tpng)");
                  return [dot]() {
                    const auto diagram = examples::BuildPendulumDiagram(examples::PendulumExampleOptions{});
                    if (*dot) {
                      std::cout << diagram->GetGraphvizString();
                      return 0;
                    }
                    std::cout << "diagram '" << diagram->get_name() << "'\n";
                    for (const systems::System* system : diagram->GetSystems()) {
                      std::cout << "  system " << system->get_name() << " (" << system->num_input_ports()
                                << " in, " << system->num_output_ports() << " out, "
                                << system->num_continuous_states() << " continuous states)\n";
                    }
                    const auto systems = diagram->GetSystems();
                    for (const auto& [input, output] : diagram->connections()) {
                      const systems::System& from = *systems[output.first];
                      const systems::System& to = *systems[input.first];
                      std::cout << "  " << from.get_name() << "." << from.get_output_port(output.second).get_name()
                                << " -> " << to.get_name() << "." << to.get_input_port(input.second).get_name()
                                << "\n";
                    }
                    return 0;
                  };
                });
}

}  // namespace cairn::cli
