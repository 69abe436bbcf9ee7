// Walks a footstep scenario in the physics plant: the planning chain of thesis Fig. 5.1 from the footstep planner
// on, as one diagram, run by the Simulator. Copy this to compose your own walk (another stabiliser, a perceived
// terrain instead of the scenario's, a torque input...).
//
//   walk_example [scenario.yaml] [--dot]
//
// Without a scenario it walks examples/scenarios/flat.yaml. With --dot it prints the diagram as Graphviz and stops
// (render with: walk_example --dot | dot -Tpng > walk.png). The transition oracle is cached in
// ./walk-example-oracles (built once, a few minutes).
#include <cstdio>
#include <cstring>
#include <exception>
#include <iostream>
#include <memory>
#include <string>

#include <cairn/multibody/plant/joint_pd_controller.h>
#include <cairn/multibody/urdf_parser.h>
#include <cairn/planning/locomotion/transition_oracle.h>
#include <cairn/planning/locomotion/walking_model.h>
#include <cairn/planning/scenarios/footstep_scenario.h>
#include <cairn/planning/walk/walk_diagram.h>
#include <cairn/planning/walk/walk_run.h>

using namespace cairn;

int main(int argc, char** argv) {
  try {
    std::string scenario_path = std::string(CAIRN_SOURCE_DIR) + "/examples/scenarios/flat.yaml";
    bool dot = false;
    for (int i = 1; i < argc; ++i) {
      if (std::strcmp(argv[i], "--dot") == 0) {
        dot = true;
      } else {
        scenario_path = argv[i];
      }
    }
    const std::string robots = std::string(CAIRN_SOURCE_DIR) + "/data/robots/";

    // The problem: the scenario's terrain, start and goal; the robot's walking model and its oracle of steps.
    const planning::FootstepScenario scenario = planning::FootstepScenario::Load(scenario_path);
    const auto objective = planning::ParseWalkingObjective(scenario.objective());
    const auto walking = std::make_shared<const planning::WalkingModel>(
        planning::WalkingModel::Load(robots + "cairn_humanoid_walking.yaml"));
    const auto oracle = std::make_shared<const planning::TransitionOracle>(planning::TransitionOracle::LoadOrBuild(
        "walk-example-oracles/" + walking->name() + "-" + to_string(objective) + ".oracle", *walking, objective,
        planning::OracleGrid::Default(*walking), planning::OracleBuildOptions(), &std::cerr));

    // The body that walks: the humanoid with a floating base and its PD gains (the setup adds its motors, for E_ele).
    multibody::UrdfOptions urdf;
    urdf.floating_base = true;
    const auto robot = std::make_shared<const multibody::Model>(
        multibody::ParseUrdfFile(robots + "cairn_humanoid.urdf", urdf));
    const auto controller = std::make_shared<const multibody::JointPdController>(
        multibody::JointPdController::Load(*robot, robots + "cairn_humanoid_control.yaml"));

    // The diagram: every block's options can be changed here before it is built.
    planning::WalkSetup setup =
        planning::WalkSetupFromScenario(scenario, oracle, walking, objective, robot, controller);
    setup.stabilizer.method = "preview";  // or "fft" (the thesis' compensation) or "none"
    const planning::WalkDiagram walk = planning::BuildWalkDiagram(setup);
    if (dot) {
      std::cout << walk.diagram->GetGraphvizString();
      return 0;
    }

    // Run it: the planners settle first (InitializeWalk), then the plant walks the stabilised reference.
    const planning::WalkRecord record = planning::RunWalk(walk);
    if (!record.start.ready) {
      std::printf("not walked: %s\n", record.start.reason.c_str());
      return 0;
    }
    std::printf("%zu steps planned over %.2f s; walked %.2f s, %s, %zu slips, E_ele %.1f J\n",
                record.plan.steps.size(), record.plan.duration, record.duration,
                record.fell ? record.fall_reason.c_str() : "no fall", record.slips.size(),
                record.samples.back().electrical_energy);
    const Eigen::VectorXd& q = record.samples.back().q;
    std::printf("base at (%.3f, %.3f, %.3f) m at the end\n", q[0], q[1], q[2]);
  } catch (const std::exception& error) {
    std::fprintf(stderr, "walk_example: %s\n", error.what());
    return 1;
  }
  return 0;
}
