// Cairn::planning_walk: the thesis' narrow-ice scenario as the physics plant's terrain; the ice is its own box of
// the true friction 0.06 and the ground around it is cut into boxes that do not overlap it.
#include <cmath>
#include <cstdio>

#include <cairn/planning/scenarios/footstep_scenario.h>
#include <cairn/planning/walk/scenario_terrain_boxes.h>

int main() {
  using namespace cairn::planning;
  const FootstepScenario scenario = FootstepScenario::Load(CAIRN_SCENARIO_YAML);
  const auto boxes = ScenarioTerrainBoxes(scenario);
  int ice = 0;
  for (const auto& box : boxes) {
    if (box.name == "ice" && std::abs(box.friction - 0.06) < 1e-12) ++ice;
  }
  std::printf("consumer planning_walk: '%s' as %zu terrain boxes, %d of ice\n", scenario.name().c_str(), boxes.size(),
              ice);
  return boxes.size() == 5 && ice == 1 ? 0 : 1;
}
