// Cairn::perception_evaluation: scores a grid holding exactly the bars scene's ground truth (precision and recall
// must be 1) and one with nothing in it (recall 0).
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <vector>

#include <cairn/perception/evaluation/occupancy_score.h>
#include <cairn/perception/occupancy/occupancy_grid.h>
#include <cairn/perception/synthetic/bars_scenario.h>

int main() {
  using namespace cairn::perception;
  const BarsScenario scenario = BarsScenario::Make(1);
  OccupancyGrid grid(scenario.grid_min_corner, scenario.grid_resolution, scenario.grid_dims);
  const OccupancyGrid empty = grid;
  const std::vector<uint8_t> truth = RasterizeScene(scenario.scene, grid);
  for (std::size_t i = 0; i < truth.size(); ++i) {
    if (truth[i]) grid.Update(i, 3.0f);
  }
  const OccupancyScore score = ScoreOccupancy(grid, truth);
  const OccupancyScore nothing = ScoreOccupancy(empty, truth);
  std::printf("consumer perception_evaluation: %zu occupied cells, precision %.3f, recall %.3f\n",
              score.num_occupied, score.precision, score.recall);
  const bool right = score.num_occupied > 0 && score.precision == 1.0 && score.recall == 1.0 && nothing.recall == 0.0;
  return right ? 0 : 1;
}
