#pragma once

/// @file
/// Loading rectified pairs with ground-truth disparity in the Middlebury 2001 layout.

#include <string>

#include <opencv2/core.hpp>

namespace cairn::perception {

/// Reads an image as 8-bit grey through ReadImageFile(), so its size is checked against kMaxImagePixels before it
/// is decoded. Throws std::runtime_error naming the path when it is missing, unreadable or corrupt, and
/// std::invalid_argument when it is too large or not a PNG, JPEG, PNM or BMP file.
cv::Mat LoadGrayImage(const std::string& path);

/// The scale KITTI's 16-bit disparity PNGs use: disparity = value / 256, value 0 = invalid.
inline constexpr double kKittiDisparityScale = 256.0;

/// Reads a ground-truth disparity PNG and divides its values by `scale` (file value per pixel of disparity).
/// The bit depth is taken from the file, never reduced: 8-bit files are the Middlebury 2001-2006 layout (grey, or
/// grey copied into three channels; scale 8 for the 2001 pairs, 16 for tsukuba, 4 for 2003 quarter size, 3 for
/// 2005-2006 third size), 16-bit files the KITTI layout (scale kKittiDisparityScale). Value 0 means unknown in
/// both. Returns CV_32FC1 in pixels. Throws std::invalid_argument if `scale` is not positive and finite, or the
/// file is colour-coded (channels that differ) or neither 8- nor 16-bit; otherwise as LoadGrayImage().
cv::Mat LoadDisparityImage(const std::string& path, double scale);

/// LoadDisparityImage() with the scale its layout documents: kKittiDisparityScale for a 16-bit file. An 8-bit
/// file has no standard scale (Middlebury's differ per data set), so it throws std::invalid_argument asking for
/// one.
cv::Mat LoadDisparityImage(const std::string& path);

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
