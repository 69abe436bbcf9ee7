#pragma once

/// @file
/// StereoSource: a recorded sequence of rectified pairs with calibration and camera poses, from a YAML file.

#include <string>
#include <vector>

#include <Eigen/Geometry>
#include <opencv2/core.hpp>

#include "cairn/perception/stereo/stereo_calibration.h"
#include "cairn/systems/framework/leaf_system.h"

namespace cairn::perception {

/// Plays back a sequence described by a YAML file; image paths are relative to the file's folder:
/// @code{.yaml}
/// calibration: {fx: 500, fy: 500, cx: 319.5, cy: 239.5, baseline: 0.1}
/// frames:
///   - {left: left_000.png, right: right_000.png,
///      translation: [0, 0, 0], rotation_wxyz: [1, 0, 0, 0]}   # X_WC of the left camera
/// @endcode
/// Every image is read (as 8-bit grey, through ReadImageFile()) and checked when the source is built, so a bad file
/// fails at once. A source holds at most 100000 frames and 2^30 pixels in all its images.
/// Frame k = floor(t / period) is shown at time t (the last one after the sequence ends).
///
/// | port | type | meaning |
/// |---|---|---|
/// | output `left` | cv::Mat (CV_8UC1) | rectified left image |
/// | output `right` | cv::Mat (CV_8UC1) | rectified right image |
/// | output `X_WC` | Eigen::Isometry3d | left camera pose in the world |
///
/// No state; outputs depend on time only.
class StereoSource final : public systems::LeafSystem {
 public:
  /// Reads `yaml_path`. Throws std::invalid_argument naming the file, the line and the problem (unreadable or
  /// malformed file, missing, unknown or repeated key, non-finite number, unreadable or too large image, more than
  /// 100000 frames or 2^30 pixels in all, left/right size mismatch, bad calibration) or a bad period.
  StereoSource(const std::string& yaml_path, double period);

  const StereoCalibration& calibration() const { return calibration_; }
  int num_frames() const { return static_cast<int>(left_.size()); }
  double period() const { return period_; }
  /// The frame shown at time t.
  int FrameIndexAt(double t) const;

  const systems::OutputPort& get_left_output_port() const { return get_output_port(0); }
  const systems::OutputPort& get_right_output_port() const { return get_output_port(1); }
  const systems::OutputPort& get_pose_output_port() const { return get_output_port(2); }

 private:
  StereoCalibration calibration_;
  double period_;
  std::vector<cv::Mat> left_;
  std::vector<cv::Mat> right_;
  std::vector<Eigen::Isometry3d> poses_;
};

}  // namespace cairn::perception
