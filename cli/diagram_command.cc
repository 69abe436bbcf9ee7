// `cairn diagram`: shows the example diagram's structure, as text or as Graphviz dot.

#include <iostream>
#include <memory>

#include "cairn/multibody/plant/joint_pd_controller.h"
#include "cairn/multibody/urdf_parser.h"
#include "cairn/perception/friction/make_material_segmenter.h"
#include "cairn/planning/run/main_diagram.h"
#include "cairn/planning/run/scenario_stereo_scene.h"
#include "cairn/planning/scenarios/footstep_scenario.h"
#include "cairn/planning/walk/walk_diagram.h"
#include "choice_option.h"
#include "command_registry.h"
#include "data_directory.h"
#include "examples/systems/pendulum_example.h"
#include "file_checks.h"
#include "oracle_cache.h"
#include "usage_error.h"

namespace cairn::cli {
namespace {

// The walk diagram of `cairn walk` (planning/walk) for a scenario; its footstep planner needs the oracle, loaded
// from the cache (or built once).
// With `perceive`, the main diagram of `cairn run` (planning/run): the head camera and perception in front of it.
planning::WalkDiagram WalkExample(const std::string& scenario_path, const std::string& cache, bool perceive) {
  CheckInputFile("--scenario", scenario_path, "a scenario YAML file");
  const planning::FootstepScenario scenario = planning::FootstepScenario::Load(scenario_path);
  if (perceive) planning::ScenarioStereoScene(scenario);  // a scenario the camera cannot see fails before the oracle
  const planning::WalkingObjective objective = planning::ParseWalkingObjective(scenario.objective());
  const std::string walking = scenario.robot().empty() ? DataDirectory() + "/robots/cairn_humanoid_walking.yaml"
                                                       : scenario.robot();
  const auto walking_model = std::make_shared<const planning::WalkingModel>(planning::WalkingModel::Load(walking));
  const auto oracle = std::make_shared<const planning::TransitionOracle>(
      LoadOrBuildOracle(cache.empty() ? DefaultOracleCache() : cache, *walking_model, objective));
  multibody::UrdfOptions urdf;
  urdf.floating_base = true;
  const auto robot = std::make_shared<const multibody::Model>(
      multibody::ParseUrdfFile(DataDirectory() + "/robots/cairn_humanoid.urdf", urdf));
  const auto controller = std::make_shared<const multibody::JointPdController>(
      multibody::JointPdController::Load(*robot, DataDirectory() + "/robots/cairn_humanoid_control.yaml"));
  const planning::WalkSetup setup =
      planning::WalkSetupFromScenario(scenario, oracle, walking_model, objective, robot, controller);
  if (!perceive) return planning::BuildWalkDiagram(setup);
  const planning::SyntheticCamera camera;
  const planning::PerceptionSetup perception = planning::PerceptionSetupFromScenario(
      scenario, camera.Calibration(),
      perception::MakeMaterialSegmenter("builtin:" + DataDirectory() + "/models/builtin_material_segmenter.yaml"));
  return planning::BuildMainDiagram(setup, perception,
                                    planning::ScenarioCamera(scenario, camera, perception.period))
      .walk;
}

}  // namespace

void RegisterDiagramCommand(CommandRegistry* registry) {
  registry->Add("diagram", "Print the example diagram (systems and connections, or Graphviz with --dot)",
                [](CLI::App& app) -> CommandAction {
                  auto dot = std::make_shared<bool>(false);
                  app.add_flag("--dot", *dot, "Print Graphviz dot (render with: cairn diagram --dot | dot -Tpng)");
                  auto example = std::make_shared<std::string>();
                  AddChoiceOption(app, "--example", example.get(),
                                  "Which diagram (default: pendulum; main when --scenario is given)",
                                  {"pendulum", "walk", "main"});
                  auto scenario = std::make_shared<std::string>();
                  app.add_option("--scenario", *scenario,
                                 "The scenario YAML of the walk (cairn walk) or main (cairn run) diagram");
                  auto cache = std::make_shared<std::string>();
                  app.add_option("--oracle-cache", *cache,
                                 "With --example walk: folder caching transition oracles (default "
                                 "$XDG_CACHE_HOME/cairn/oracles)");
                  return [dot, example, scenario, cache]() {
                    planning::WalkDiagram walk;
                    std::unique_ptr<systems::Diagram> pendulum;
                    const std::string which = !example->empty() ? *example : scenario->empty() ? "pendulum" : "main";
                    if (which == "walk" || which == "main") {
                      if (scenario->empty()) {
                        throw UsageError("--example " + which + " needs --scenario S.yaml (e.g. examples/scenarios/" +
                                         (which == "walk" ? "flat.yaml" : "mockup/mockup.yaml") + ")");
                      }
                      walk = WalkExample(*scenario, *cache, which == "main");
                    } else if (!scenario->empty()) {
                      throw UsageError("--scenario is for the walk and main diagrams; drop it or use --example main");
                    } else {
                      pendulum = examples::BuildPendulumDiagram(examples::PendulumExampleOptions{});
                    }
                    const systems::Diagram* diagram = pendulum ? pendulum.get() : walk.diagram.get();
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
