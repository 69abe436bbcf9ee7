#pragma once

/// @file
/// A small deterministic ray-caster that renders rectified stereo pairs with ground truth.

#include <cstdint>

#include <Eigen/Geometry>
#include <opencv2/core.hpp>

#include "cairn/perception/stereo/stereo_calibration.h"
#include "cairn/perception/synthetic/synthetic_stereo_scene.h"

namespace cairn::perception {

/// One rendered frame.
struct SyntheticStereoFrame {
  /// Left image, CV_8UC1.
  cv::Mat left;
  /// Right image, CV_8UC1 (camera at +baseline along the left camera's x axis).
  cv::Mat right;
  /// Ground-truth depth (z in the left camera frame, metres) of the left view, CV_32FC1; +infinity where the
  /// ray hits nothing.
  cv::Mat depth;
  /// Ground-truth material label of the left view, CV_32SC1; -1 where the ray hits nothing.
  cv::Mat labels;
  /// Left and right colour images, CV_8UC3 (BGR), rendered only for scenes with colour textures
  /// (SyntheticStereoScene::has_colour_textures()), else empty. `left` and `right` are then their luma
  /// (0.299 R + 0.587 G + 0.114 B, before noise).
  cv::Mat left_colour;
  cv::Mat right_colour;
  /// Pose of the left camera in the world.
  Eigen::Isometry3d X_WC{Eigen::Isometry3d::Identity()};
};

/// Renders rectified pairs of a SyntheticStereoScene by casting rays through every pixel (2 x 2 supersampling for
/// the intensities, the pixel centre for depth and labels), with optional Gaussian image noise. The result of
/// Render() depends only on the scene, the pose, the frame index and the constructor's arguments. Scenes with
/// colour textures are also rendered in colour (the colour images' noise is drawn independently per channel).
class SyntheticStereoRenderer {
 public:
  /// `noise_variance` is the variance of the zero-mean Gaussian noise added to each image's intensities (0..255
  /// scale); `seed` seeds the noise. Throws std::invalid_argument for a bad calibration, a non-positive size or one
  /// above kMaxImagePixels, or a negative or non-finite variance.
  SyntheticStereoRenderer(const StereoCalibration& calibration, int width, int height, double noise_variance = 0.0,
                          std::uint32_t seed = 1);

  /// Renders the pair seen from left-camera pose X_WC; `frame_index` (>= 0, else std::invalid_argument) selects the
  /// noise realisation.
  SyntheticStereoFrame Render(const SyntheticStereoScene& scene, const Eigen::Isometry3d& X_WC,
                              int frame_index = 0) const;

  const StereoCalibration& calibration() const { return calibration_; }
  int width() const { return width_; }
  int height() const { return height_; }
  double noise_variance() const { return noise_variance_; }

  /// Intensity of rays that hit nothing (a textureless sky).
  static constexpr double kBackgroundIntensity = 128.0;

 private:
  StereoCalibration calibration_;
  int width_;
  int height_;
  double noise_variance_;
  std::uint32_t seed_;
};

}  // namespace cairn::perception
