#pragma once

/// @file
/// Loading rectified pairs with ground-truth disparity in the Middlebury 2001 layout.

#include <string>

#include <opencv2/core.hpp>

namespace cairn::perception {

/// Reads an image as 8-bit grey; throws std::runtime_error naming the path when it is missing or unreadable.
cv::Mat LoadGrayImage(const std::string& path);

/// Reads a ground-truth disparity PNG (grey, or grey copied into three channels) and divides it by `scale`
/// (Middlebury: 8, or 16 for tsukuba). Returns CV_32FC1 in pixels; 0 means unknown. Throws std::runtime_error if
/// the file is missing or unreadable, std::invalid_argument if scale is not positive.
cv::Mat LoadDisparityImage(const std::string& path, double scale);

/// Occlusion mask from a left-right check of the two ground-truth maps (CV_32FC1, pixels, 0 = unknown): a left
/// pixel with disparity d is occluded when the right map at x - d is known and differs from d by more than
/// `tolerance`, or when x - d falls outside the image. Returns CV_8UC1, 255 = occluded. Throws
/// std::invalid_argument if the maps differ in size or type.
cv::Mat OcclusionFromGroundTruth(const cv::Mat& left_disparity, const cv::Mat& right_disparity, double tolerance = 1.0);

/// A Middlebury-2001-style folder: im2.png (left), im6.png (right), disp2.png (left ground truth) and, when present,
/// disp6.png (right ground truth).
struct MiddleburyPair {
  /// Left image, 8-bit grey.
  cv::Mat left;
  /// Right image, 8-bit grey.
  cv::Mat right;
  /// Left ground-truth disparity, CV_32FC1 pixels, 0 = unknown.
  cv::Mat gt_left;
  /// Right ground-truth disparity, or empty when the folder has none.
  cv::Mat gt_right;
  /// CV_8UC1 occlusion mask (255 = occluded) from the two ground truths, or empty when there is no right one.
  cv::Mat occluded;

  /// Loads the folder; `scale` divides the ground-truth PNG values. Throws std::runtime_error naming the missing
  /// file.
  static MiddleburyPair Load(const std::string& folder, double scale);
};

}  // namespace cairn::perception
