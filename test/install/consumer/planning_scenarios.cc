// Cairn::planning_scenarios: loads the thesis' narrow-ice scenario and rasterises its terrain; the cell at the
// centre of the last region (painted last) carries that region's height and its (1 - eta) friction quantile (the
// map stores floats).
#include <cmath>
#include <cstdio>

#include <cairn/planning/footstep/terrain_map.h>
#include <cairn/planning/scenarios/footstep_scenario.h>

int main() {
  using namespace cairn::planning;
  const FootstepScenario scenario = FootstepScenario::Load(CAIRN_SCENARIO_YAML);
  const TerrainMap terrain = scenario.BuildTerrain();
  const FootstepScenario::Region& region = scenario.regions().back();
  Eigen::Vector2d centre = Eigen::Vector2d::Zero();
  for (const Eigen::Vector2d& vertex : region.polygon) centre += vertex;
  centre /= static_cast<double>(region.polygon.size());
  int col = 0, row = 0;
  const bool inside = terrain.CellAt(centre.x(), centre.y(), &col, &row);
  const double expected = region.friction.Quantile(1.0 - scenario.eta());
  std::printf("consumer planning_scenarios: '%s', %zu regions, %d x %d cells, %s friction %.3f\n",
              scenario.name().c_str(), scenario.regions().size(), terrain.cols(), terrain.rows(), region.name.c_str(),
              inside ? terrain.friction(col, row) : -1.0);
  const bool right = inside && std::abs(terrain.friction(col, row) - expected) < 1e-6 &&
                     std::abs(terrain.height(col, row) - region.HeightAt(terrain.CellCenter(col, row))) < 1e-6;
  return right ? 0 : 1;
}
