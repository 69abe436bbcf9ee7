#include "cairn/perception/evaluation/occupancy_score.h"

#include <stdexcept>
#include <string>

namespace cairn::perception {

OccupancyScore ScoreOccupancy(const OccupancyGrid& grid, const std::vector<uint8_t>& truth, double threshold) {
  if (truth.size() != grid.num_cells()) {
    throw std::invalid_argument("ScoreOccupancy: the ground truth has " + std::to_string(truth.size()) +
                                " cells but the grid has " + std::to_string(grid.num_cells()) +
                                "; rasterise the truth on the same grid (RasterizeScene)");
  }
  if (!(threshold > 0.0 && threshold < 1.0)) {
    throw std::invalid_argument("ScoreOccupancy: threshold " + std::to_string(threshold) + " must be in (0, 1)");
  }
  OccupancyScore score;
  for (std::size_t i = 0; i < truth.size(); ++i) {
    const bool occupied = truth[i] != 0;
    score.num_occupied += occupied ? 1 : 0;
    if (grid.probability(i) > threshold) {
      (occupied ? score.true_positives : score.false_positives) += 1;
    }
  }
  const std::size_t claimed = score.true_positives + score.false_positives;
  score.precision = claimed > 0 ? static_cast<double>(score.true_positives) / static_cast<double>(claimed) : 0.0;
  score.recall = score.num_occupied > 0
                     ? static_cast<double>(score.true_positives) / static_cast<double>(score.num_occupied)
                     : 0.0;
  return score;
}

std::vector<uint8_t> RasterizeScene(const SyntheticStereoScene& scene, const OccupancyGrid& grid) {
  std::vector<uint8_t> truth(grid.num_cells(), 0);
  for (std::size_t i = 0; i < truth.size(); ++i) {
    truth[i] = scene.OccupiesCube(grid.CellCenter(grid.Cell(i)), grid.resolution()) ? 1 : 0;
  }
  return truth;
}

}  // namespace cairn::perception
