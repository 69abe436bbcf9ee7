#pragma once

/// @file
/// Labelled colour scenes for material segmenters, built for and rendered by the synthetic stereo source.

#include <cstdint>
#include <string>
#include <vector>

#include <Eigen/Geometry>
#include <opencv2/core.hpp>

#include "cairn/perception/stereo/stereo_calibration.h"
#include "cairn/perception/synthetic/synthetic_stereo_renderer.h"
#include "cairn/perception/synthetic/synthetic_stereo_scene.h"

namespace cairn::perception {

/// A random family of SyntheticStereoScene's whose surfaces wear MaterialTexture's: a ground of square tiles of
/// random materials (thin boxes) over an infinite ground plane, a few boxes standing on it and a far "sky" wall,
/// seen by a stereo camera at a random height, pitch, yaw and roll. Every object's label is its material's index
/// in Options::labels, so the stereo renderer's ground-truth label image is the segmentation ground truth and its
/// left colour image the segmenter's input; the grey pair and depth come with it for stereo.
///
/// MakeScenario(seed) and Render(seed) depend only on the options and the seed. Lighting is a per-scene colour
/// tint and gain times a per-object brightness (the stereo renderer itself is unlit).
class StereoMaterialScene {
 public:
  /// What to build.
  struct Options {
    /// Image size in pixels; > 0.
    int width{160};
    int height{120};
    /// Horizontal field of view in degrees, in (10, 150).
    double field_of_view_deg{70.0};
    /// Stereo baseline in metres; > 0.
    double baseline{0.12};
    /// The label space (label image values index it). Defaults to MaterialTexture's labels.
    std::vector<std::string> labels;
    /// Materials of the ground tiles and plane; default: every label but "sky". Each must be in `labels`.
    std::vector<std::string> ground_labels;
    /// Materials of the standing boxes; default: wood, metal, marble, rock, ceramic, carpet, cloth, paper (those
    /// in `labels`). Each must be in `labels`.
    std::vector<std::string> box_labels;
    /// Ground tiles per side of the square tile grid; >= 1.
    int tiles_per_side{3};
    /// Standing boxes; >= 0.
    int num_boxes{2};
    /// Variance of the renderer's Gaussian image noise (0..255 scale); >= 0.
    double noise_variance{4.0};
  };

  /// One scene of the family: hand it to a SyntheticStereoSource (with a trajectory through X_WC) or render it.
  struct Scenario {
    SyntheticStereoScene scene;
    /// Left camera pose in the world (world z up).
    Eigen::Isometry3d X_WC{Eigen::Isometry3d::Identity()};
  };

  /// One render.
  struct Rendering {
    /// Left colour image, CV_8UC3 (BGR): the segmenter's input.
    cv::Mat image;
    /// CV_8UC1: index into Options::labels per pixel, 255 where the ray meets nothing.
    cv::Mat labels;
    /// The full stereo frame (grey pair, depth, CV_32S labels, colour pair).
    SyntheticStereoFrame frame;
  };

  /// Validates and completes the options; throws std::invalid_argument naming the bad option and its value.
  explicit StereoMaterialScene(Options options);

  /// Scene number `seed` of the family.
  Scenario MakeScenario(std::uint32_t seed) const;
  /// Renders scene number `seed` with renderer() (noise realisation `seed`).
  Rendering Render(std::uint32_t seed) const;

  /// The calibration implied by the options (square pixels, principal point at the image centre).
  const StereoCalibration& calibration() const { return calibration_; }
  /// The renderer Render() uses (the options' size and noise).
  const SyntheticStereoRenderer& renderer() const { return renderer_; }
  const Options& options() const { return options_; }

 private:
  Options options_;
  StereoCalibration calibration_;
  SyntheticStereoRenderer renderer_;
};

}  // namespace cairn::perception
