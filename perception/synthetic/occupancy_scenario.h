#pragma once

/// @file
/// A synthetic occupancy-grid experiment: scene, stereo camera and its trajectory, image noise and evaluation grid.

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "cairn/perception/stereo/stereo_calibration.h"
#include "cairn/perception/synthetic/synthetic_stereo_scene.h"

namespace cairn::perception {

/// Everything `cairn occupancy` needs to render a stereo sequence of a synthetic scene, fuse it into a grid and
/// score the grid against the scene's own ground truth (RasterizeScene). BarsScenario::ToOccupancyScenario()
/// gives the built-in scene of thesis Figs. 4.7/4.8; FromYaml() reads one from a file whose schema is documented
/// in docs/occupancy_scenarios.md.
struct OccupancyScenario {
  /// Limits on what a scenario file may state, each checked before anything is allocated from it: frames of an
  /// orbit or poses listed (10000, 1.3 MB of poses; a rendered frame takes ~10 ms at VGA), objects (1000: every
  /// pixel ray meets every object), named textures, an image side (8192 px, kMaxImagePixels), a label, the noise
  /// variance (255^2), and the magnitude of a coordinate, length or angle (1e4).
  static constexpr int kMaxFrames = 10000;
  /// See kMaxFrames.
  static constexpr int kMaxObjects = 1000;
  /// See kMaxFrames.
  static constexpr int kMaxTextures = 1000;
  /// See kMaxFrames.
  static constexpr int kMaxImageSide = 8192;
  /// See kMaxFrames.
  static constexpr int kMaxLabel = 65535;
  /// See kMaxFrames.
  static constexpr double kMaxNoiseVariance = 255.0 * 255.0;
  /// See kMaxFrames.
  static constexpr double kMaxCoordinate = 1e4;
  /// Largest scenario file (2 MiB), refused from its size before it is parsed: the limits above admit files of
  /// under a megabyte (10000 poses and 1000 objects take about 700 KB), and parsing takes time and memory in
  /// proportion to the file.
  static constexpr std::size_t kMaxFileBytes = 2u << 20;

  /// The scene (textured planes and boxes, each with a material label).
  SyntheticStereoScene scene;
  /// The rectified stereo camera.
  StereoCalibration calibration;
  /// Image size (pixels).
  int width{640};
  /// See width.
  int height{480};
  /// Disparity range matched (min_disparity >= 1 so that every ray ends at a finite depth).
  int min_disparity{1};
  /// See min_disparity.
  int max_disparity{64};
  /// Variance of the Gaussian noise added to the images (0..255 scale); 0 renders noise-free images.
  double noise_variance{0.0};
  /// Seed of the image noise.
  std::uint32_t seed{1};
  /// Left-camera poses in the world, one per frame.
  std::vector<Eigen::Isometry3d> trajectory;
  /// The evaluation grid: minimum corner (world frame), cell side (metres) and cells per axis.
  Eigen::Vector3d grid_min_corner{Eigen::Vector3d::Zero()};
  /// See grid_min_corner.
  double grid_resolution{0.05};
  /// See grid_min_corner.
  Eigen::Vector3i grid_dims{Eigen::Vector3i::Ones()};

  /// Reads a scenario from a YAML file (schema: docs/occupancy_scenarios.md). Throws std::invalid_argument naming
  /// the file, the offending key (e.g. `objects[2].half_extents`) and its line for a missing, unknown, repeated,
  /// mistyped or out-of-range entry (the limits above; seeds in [0, 2^32 - 1]), and for a file that cannot be read
  /// or parsed.
  static OccupancyScenario FromYaml(const std::string& path);

  /// The camera pose at `position` looking at `target` with the world's +z up in the image (the image's y axis
  /// points down). Throws std::invalid_argument if the two points coincide or the view is vertical.
  static Eigen::Isometry3d LookAt(const Eigen::Vector3d& position, const Eigen::Vector3d& target);
};

}  // namespace cairn::perception
