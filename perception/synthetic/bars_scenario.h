#pragma once

/// @file
/// The visually repetitive scene of thesis Figs. 4.7/4.8: seven thin identical vertical bars.

#include <vector>

#include <Eigen/Geometry>

#include "cairn/perception/stereo/stereo_calibration.h"
#include "cairn/perception/synthetic/occupancy_scenario.h"
#include "cairn/perception/synthetic/synthetic_stereo_scene.h"

namespace cairn::perception {

/// Seven identical, identically textured vertical bars (8 cm square, 30 cm apart, 3 m from the camera path's
/// centre; world z up) 1 m in front of a textured wall (just beyond the evaluation grid), seen by a 640 x 480
/// stereo camera (fx = 600 px, 56 degrees horizontal field of view, baseline 0.3 m) moving on an arc of +-25
/// degrees around them while looking at their centre. Seen head-on, a bar's image repeats every 60 px while its
/// disparity is 60 px, so every bar also matches its neighbour at disparity 120: WTA stereo sees ghost bars at
/// 1.5 m.
///
/// The camera resolves the grid: at 3 m one disparity step is 5 cm deep (z^2 / (fx b)), one cell, and the 4 px
/// by which a 9 x 9 window fattens a bar's silhouette is 2 cm. With half the focal length (320 x 240) the step is
/// 10 cm, two cells: a cell in front of or behind a bar then shares the bar's disparity sample, and no fusion
/// over views from within +-25 degrees can tell them apart (cost-curve precision 0.49 instead of 0.98, measured).
struct BarsScenario {
  /// The scene (bars carry label 1, the wall label 2).
  SyntheticStereoScene scene;
  /// One scene per bar, for per-bar ground truth.
  std::vector<SyntheticStereoScene> bars;
  /// The camera.
  StereoCalibration calibration;
  /// Image size.
  int width{640};
  /// Image size.
  int height{480};
  /// Disparity range matched (covers the wall, the bars and their ghosts).
  int min_disparity{16};
  /// See min_disparity.
  int max_disparity{142};
  /// Left-camera poses in the world, one per frame.
  std::vector<Eigen::Isometry3d> trajectory;
  /// The evaluation grid: minimum corner, cell size and dimensions (it covers the bars and the ghost zone).
  Eigen::Vector3d grid_min_corner{-1.3, 1.2, -0.3};
  /// Cell side (metres).
  double grid_resolution{0.05};
  /// Cells per axis.
  Eigen::Vector3i grid_dims{52, 54, 12};

  /// Builds the scenario with `frames` camera poses (1 to OccupancyScenario::kMaxFrames; throws
  /// std::invalid_argument otherwise).
  static BarsScenario Make(int frames = 20);

  /// The same experiment as a generic OccupancyScenario (noise-free, seed 1), as `cairn occupancy` runs it.
  OccupancyScenario ToOccupancyScenario() const;
};

}  // namespace cairn::perception
