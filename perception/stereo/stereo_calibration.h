#pragma once

/// @file
/// Pinhole calibration of a rectified stereo pair.

#include <string>

namespace cairn::perception {

/// Intrinsics of the rectified left camera and the baseline to the right camera (camera frame: x right, y down,
/// z forward; the right camera sits at +baseline along x). Depth z and disparity d relate by z = fx baseline / d.
struct StereoCalibration {
  /// Focal length along x (pixels).
  double fx{500.0};
  /// Focal length along y (pixels).
  double fy{500.0};
  /// Principal point x (pixels).
  double cx{320.0};
  /// Principal point y (pixels).
  double cy{240.0};
  /// Distance between the optical centres (metres).
  double baseline{0.1};

  /// Throws std::invalid_argument naming the first non-positive or non-finite focal length or baseline, or a
  /// non-finite principal point.
  void Validate() const;
  /// fx * baseline: depth times disparity.
  double depth_times_disparity() const { return fx * baseline; }
};

}  // namespace cairn::perception
