// The main diagram on thesis 5.2.3's mock-up: a robot looks at a floor of wood and ceramic tiles through its head
// camera, reconstructs the geometry (cost-curve occupancy) and the friction (materials -> distributions ->
// quantiles), assembles the terrain, plans footsteps and timing on it, optimises the whole body, stabilises it and
// walks it in the physics plant. One diagram, run by the Simulator; copy it to swap any block.
//
//   mockup_example [scenario.yaml] [--dot]
//
// Without a scenario it runs examples/scenarios/mockup/mockup.yaml (its variants: mockup_cloth.yaml,
// mockup_obstacle.yaml). With --dot it prints the diagram as Graphviz and stops. The transition oracle is cached in
// ./walk-example-oracles (built once, a few minutes; shared with walk_example).
#include <cstdio>
#include <cstring>
#include <exception>
#include <iostream>
#include <memory>
#include <string>

#include <cairn/multibody/plant/joint_pd_controller.h>
#include <cairn/multibody/urdf_parser.h>
#include <cairn/perception/friction/make_material_segmenter.h>
#include <cairn/planning/locomotion/transition_oracle.h>
#include <cairn/planning/locomotion/walking_model.h>
#include <cairn/planning/run/main_diagram.h>
#include <cairn/planning/run/scenario_stereo_scene.h>
#include <cairn/planning/scenarios/footstep_scenario.h>

using namespace cairn;

int main(int argc, char** argv) {
  try {
    const std::string source = CAIRN_SOURCE_DIR;
    std::string scenario_path = source + "/examples/scenarios/mockup/mockup.yaml";
    bool dot = false;
    for (int i = 1; i < argc; ++i) {
      if (std::strcmp(argv[i], "--dot") == 0) {
        dot = true;
      } else {
        scenario_path = argv[i];
      }
    }
    const std::string robots = source + "/data/robots/";

    // The problem and the walker: as examples/walk.
    const planning::FootstepScenario scenario = planning::FootstepScenario::Load(scenario_path);
    const auto objective = planning::ParseWalkingObjective(scenario.objective());
    const auto walking = std::make_shared<const planning::WalkingModel>(
        planning::WalkingModel::Load(robots + "cairn_humanoid_walking.yaml"));
    const auto oracle = std::make_shared<const planning::TransitionOracle>(planning::TransitionOracle::LoadOrBuild(
        "walk-example-oracles/" + walking->name() + "-" + to_string(objective) + ".oracle", *walking, objective,
        planning::OracleGrid::Default(*walking), planning::OracleBuildOptions(), &std::cerr));
    multibody::UrdfOptions urdf;
    urdf.floating_base = true;
    const auto robot = std::make_shared<const multibody::Model>(
        multibody::ParseUrdfFile(robots + "cairn_humanoid.urdf", urdf));
    const auto controller = std::make_shared<const multibody::JointPdController>(
        multibody::JointPdController::Load(*robot, robots + "cairn_humanoid_control.yaml"));
    planning::WalkSetup walk =
        planning::WalkSetupFromScenario(scenario, oracle, walking, objective, robot, controller);

    // The eyes: a synthetic stereo head camera looking at the scenario's floor, and the perception behind it.
    const planning::SyntheticCamera camera;  // 320x240, 70 degrees, 12 cm baseline, 1.3 m up, pitched 70 degrees
    const auto segmenter =
        perception::MakeMaterialSegmenter("builtin:" + source + "/data/models/builtin_material_segmenter.yaml");
    const planning::PerceptionSetup perception =
        planning::PerceptionSetupFromScenario(scenario, camera.Calibration(), segmenter);

    const planning::MainDiagram main = planning::BuildMainDiagram(
        walk, perception, planning::ScenarioCamera(scenario, camera, perception.period));
    if (dot) {
      std::cout << main.walk.diagram->GetGraphvizString();
      return 0;
    }

    // Run it: perceive the first frame, plan on what was seen, then walk.
    const planning::MainRecord record = planning::RunMainDiagram(main);
    std::printf("perception %.2f s; terrain %d x %d cells\n", record.perception_seconds,
                record.terrain ? record.terrain->cols() : 0, record.terrain ? record.terrain->rows() : 0);
    if (!record.walk.start.ready) {
      std::printf("not walked: %s\n", record.walk.start.reason.c_str());
      return 0;
    }
    for (const planning::PlannedStep& step : record.walk.plan.steps) {
      std::printf("  %s foot to (%5.2f, %5.2f), friction it may use %.2f\n",
                  step.side == planning::FootSide::kLeft ? "left " : "right", step.pose.x, step.pose.y,
                  step.mu_allowed);
    }
    std::printf("%zu steps over %.2f s; walked %.2f s, %s, %zu slips\n", record.walk.plan.steps.size(),
                record.walk.plan.duration, record.walk.duration,
                record.walk.fell ? record.walk.fall_reason.c_str() : "no fall", record.walk.slips.size());
  } catch (const std::exception& error) {
    std::fprintf(stderr, "mockup_example: %s\n", error.what());
    return 1;
  }
  return 0;
}
