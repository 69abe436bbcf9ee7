// The probing example (seed 001): builds the diagram of planning/scenarios/probing_diagram.h on a traverse scenario
// (default: the shipped plants_and_water.yaml) and runs it until the robot reaches its goal.
//
//   probing_diagram [scenario.yaml]

#include <cstdio>
#include <exception>
#include <string>

#include "cairn/planning/scenarios/probing_diagram.h"

int main(int argc, char** argv) {
  try {
    const std::string path =
        argc > 1 ? argv[1] : std::string(CAIRN_SOURCE_DIR) + "/examples/scenarios/traverse/plants_and_water.yaml";
    const auto scenario = cairn::planning::TraverseScenario::Load(path);
    const auto run = cairn::planning::RunProbingDiagram(
        scenario, std::string(CAIRN_SOURCE_DIR) + "/data/robots/cairn_probe_arm.urdf", 300.0);
    std::printf("%s after %.1f s at (%.2f, %.2f); %d probes:", run.reached_goal ? "goal reached" : "goal not reached",
                run.time, run.final_position.x(), run.final_position.y(), run.probes_made);
    for (double c : run.collapsibilities) std::printf(" C=%.2f", c);
    std::printf("\n");
    return run.reached_goal ? 0 : 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "probing_diagram: error: %s\n", e.what());
    return 1;
  }
}
