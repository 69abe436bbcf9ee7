#pragma once

/// @file
/// DisparityToDepth: the winner-take-all disparity of a rectified pair as a depth image.

#include <opencv2/core.hpp>

#include "cairn/perception/stereo/stereo_calibration.h"
#include "cairn/perception/stereo/winner_take_all.h"
#include "cairn/systems/framework/leaf_system.h"

namespace cairn::perception {

/// Which winner-take-all disparities DisparityToDepth trusts.
struct DisparityToDepthOptions {
  /// Keep only pixels whose left and right winners agree (WtaResult::lr_consistent).
  bool require_left_right{true};
  /// Keep only pixels whose cost curve's second minimum is at least this many times the first; >= 1 (1 keeps all).
  double min_peak_ratio{1.0};
};

/// Depth z = fx * baseline / d of every left pixel whose winner is trusted, NaN elsewhere: the geometry that
/// per-pixel consumers (FrictionEstimator's friction points) attach to an image. The occupancy grid reads the whole
/// confidence volume instead; this is the point estimate for systems that need one depth per pixel.
///
/// | port | type | meaning |
/// |---|---|---|
/// | input `wta` | WtaResult | StereoMatcher's `wta` |
/// | output `depth` | cv::Mat (CV_32F) | depth along the optical axis (m); NaN where the winner is not trusted |
///
/// A winner is trusted when its disparity is positive and finite, it passed the left-right check (unless
/// Options::require_left_right is false) and its peak ratio is at least Options::min_peak_ratio.
class DisparityToDepth final : public systems::LeafSystem {
 public:
  using Options = DisparityToDepthOptions;

  /// Throws std::invalid_argument for a bad calibration or a peak ratio below 1 or not finite.
  explicit DisparityToDepth(const StereoCalibration& calibration, const Options& options = Options());

  const StereoCalibration& calibration() const { return calibration_; }
  const Options& options() const { return options_; }

  const systems::InputPort& get_wta_input_port() const { return get_input_port(0); }
  const systems::OutputPort& get_depth_output_port() const { return get_output_port(0); }

  /// The conversion the output computes: `depth` gets wta.disparity's size. Throws std::invalid_argument when the
  /// result's disparity is not CV_32F or its check images do not match it.
  void Convert(const WtaResult& wta, cv::Mat* depth) const;

 private:
  StereoCalibration calibration_;
  Options options_;
};

}  // namespace cairn::perception
