#pragma once

/// @file
/// Evaluation of stereo confidence against ground truth (thesis section 4.3.4).

#include <cstddef>
#include <cstdint>
#include <vector>

#include <opencv2/core.hpp>

#include "cairn/perception/stereo/disparity_volume.h"
#include "cairn/perception/stereo/winner_take_all.h"

namespace cairn::perception {

/// Which pixels count and what counts as an error.
struct StereoEvaluationOptions {
  /// A pixel is bad when |WTA disparity - true disparity| exceeds this (pixels). As in the thesis, the WTA
  /// disparity is the integer minimum-cost disparity d_mincost (the hypothesis whose confidence is ranked);
  /// StereoEvaluation::bad_pixel_rate_subpixel uses the sub-pixel disparity instead.
  double bad_threshold{1.0};
  /// Pixels closer than this to the image border are ignored, as OpenCV's own block-matcher tests do.
  int border{10};
  /// C(d in GT) sums the confidence of the integer disparities within this distance of the true one.
  double gt_interval{1.0};

  /// Checks the options against a `width` x `height` image; throws std::invalid_argument naming the bad value
  /// and the fix: a negative border or one that leaves no pixel (2 border >= the smaller side), a negative or
  /// non-finite bad_threshold or gt_interval.
  void Validate(int width, int height) const;
};

/// The thesis' criteria for one pair.
struct StereoEvaluation {
  /// Fraction of evaluated pixels whose integer WTA disparity is bad (the error rate the AUC ranks).
  double bad_pixel_rate{0.0};
  /// Fraction of evaluated pixels whose sub-pixel WTA disparity is off by more than the threshold (the figure
  /// OpenCV's block-matcher tests report).
  double bad_pixel_rate_subpixel{0.0};
  /// Area under the ROC curve of the WTA confidence ranking (error rate of the most confident fraction p of the
  /// pixels, integrated over p in [0, 1]); lower is better.
  double auc{0.0};
  /// The AUC of a perfect ranking at this error rate, eps + (1 - eps) ln(1 - eps).
  double auc_optimal{0.0};
  /// Mean over bad pixels of the confidence given to the true disparity's neighbourhood; higher is better.
  /// 0 when there is no bad pixel.
  double c_gt_badpx{0.0};
  /// Number of evaluated pixels.
  std::size_t num_pixels{0};
  /// Number of bad pixels among them.
  std::size_t num_bad{0};
};

/// Area under the ROC curve for a confidence ranking: pixels are taken from the most to the least confident, ties
/// entering together, and the error rate of the taken pixels is integrated (trapezoids) over the taken fraction.
/// Throws std::invalid_argument if the inputs differ in length, are empty, or a confidence is NaN (it cannot be
/// ranked).
double RocAuc(const std::vector<float>& confidence, const std::vector<uint8_t>& is_error);

/// The AUC of a perfect ranking for error rate `error_rate` in [0, 1]: eps + (1 - eps) ln(1 - eps).
double OptimalAuc(double error_rate);

/// The largest disparity to match for a pair with ground truth `ground_truth` (CV_32FC1 pixels, 0 = unknown): its
/// largest known disparity rounded up to a multiple of 16, minus 1, as block matchers expect (venus, up to 19.75
/// px: 31). Throws std::invalid_argument if the ground truth is empty or of another type, has no known pixel, holds
/// a non-finite value, or its largest disparity is not below its width (a wrong scale, most likely).
int AutomaticMaxDisparity(const cv::Mat& ground_truth);

/// Evaluates a confidence volume and its WTA disparity against a ground truth (CV_32FC1 pixels, 0 = unknown).
/// Pixels are evaluated when the ground truth is known, `occluded` (CV_8UC1, may be empty) is zero, they are at
/// least options.border from the border, their WTA disparity is valid, and the true disparity lies in the
/// volume's range with its match inside the right image. The WTA confidence of a pixel is C at its WTA
/// disparity. Throws std::invalid_argument on size or type mismatches, a WTA index outside the volume, invalid
/// options (StereoEvaluationOptions::Validate()), or if no pixel can be evaluated.
StereoEvaluation EvaluateStereo(const DisparityVolume& confidence, const WtaResult& wta, const cv::Mat& ground_truth,
                                const cv::Mat& occluded, const StereoEvaluationOptions& options = {});

}  // namespace cairn::perception
