#pragma once

/// @file
/// Stereo cost volumes (SSD and Birchfield-Tomasi SAD) with running-sum window aggregation.

#include <opencv2/core.hpp>

#include "cairn/perception/stereo/cost_volume_options.h"
#include "cairn/perception/stereo/disparity_volume.h"
#include "cairn/perception/stereo/winner_take_all.h"

namespace cairn::perception {

/// Converts an 8-bit grey or BGR image to 8-bit grey; throws std::invalid_argument for other types, naming the
/// type found.
cv::Mat ToGray8(const cv::Mat& image, const char* what);

/// OpenCV-block-matcher-style horizontal Sobel prefilter: the x derivative of `gray` (CV_8UC1) with a
/// `size` x `size` Sobel aperture (3, 5, 7 or 9), scaled so that every aperture answers a unit intensity ramp
/// like the 3x3 one, clipped to [-cap, cap] and shifted by +cap. Returns CV_8UC1 with values in [0, 2 cap].
cv::Mat SobelPrefilter(const cv::Mat& gray, int size, int cap);

/// Computes the cost volume of a rectified pair: for every left pixel (x, y) and disparity
/// d in [min_disparity, max_disparity], the window cost between the left window at (x, y) and the right window
/// at (x - d, y). Windows are aggregated by running sums (vertical then horizontal), so the work is O(W H D)
/// whatever the window size; borders replicate the edge pixels. Where x - d falls outside the right image the
/// cost is +infinity.
///
/// Intensities are integers (8-bit images, or the 8-bit prefilter output) and the sums are accumulated in
/// 32-bit integers, so costs are exact. BTSAD uses Birchfield and Tomasi's dissimilarity in both directions
/// (the minimum of left-to-right and right-to-left). `costs` is resized (its storage reused when the size is
/// unchanged).
///
/// Throws std::invalid_argument if the images are empty, differ in size or type, or the options are invalid
/// for this width (see CostVolumeOptions::Validate()).
void ComputeCostVolume(const cv::Mat& left, const cv::Mat& right, const CostVolumeOptions& options,
                       DisparityVolume* costs);

/// ComputeCostVolume() followed by ComputeWinnerTakeAll(), in one pass: each row's winners are found right after
/// the row's costs are aggregated, while they are still in cache, instead of reading the whole volume (80 MB at
/// 640x480x64) back from memory. The outputs are the same, bit for bit, as the two calls'. Rows are split by
/// `options.num_threads`; `wta_options.num_threads` is not used. Throws as the two functions do.
void ComputeCostVolumeAndWinnerTakeAll(const cv::Mat& left, const cv::Mat& right, const CostVolumeOptions& options,
                                       const WtaOptions& wta_options, DisparityVolume* costs, WtaResult* wta);

}  // namespace cairn::perception
