#pragma once

/// @file
/// Precision and recall of an occupancy grid against ground truth (thesis section 4.4.3).

#include <cstddef>
#include <cstdint>
#include <vector>

#include "cairn/perception/occupancy/occupancy_grid.h"
#include "cairn/perception/synthetic/synthetic_stereo_scene.h"

namespace cairn::perception {

/// Grid quality: a cell is claimed occupied when its probability exceeds the threshold.
struct OccupancyScore {
  /// tp / (tp + fp); 0 when no cell is claimed.
  double precision{0.0};
  /// tp / n; 0 when the ground truth has no occupied cell.
  double recall{0.0};
  /// Claimed cells that are occupied in the ground truth.
  std::size_t true_positives{0};
  /// Claimed cells that are free in the ground truth.
  std::size_t false_positives{0};
  /// Occupied cells in the ground truth.
  std::size_t num_occupied{0};
};

/// Scores `grid` against `truth` (one flag per cell, same indexing, non-zero = occupied). Throws
/// std::invalid_argument if the sizes differ or the threshold is outside (0, 1).
OccupancyScore ScoreOccupancy(const OccupancyGrid& grid, const std::vector<uint8_t>& truth, double threshold = 0.5);

/// Ground-truth occupancy of a synthetic scene on the grid's cells (a cell is occupied when any part of it is,
/// see SyntheticStereoScene::OccupiesCube).
std::vector<uint8_t> RasterizeScene(const SyntheticStereoScene& scene, const OccupancyGrid& grid);

}  // namespace cairn::perception
