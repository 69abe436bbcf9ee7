#pragma once

/// @file
/// Winner-take-all disparity from a cost volume, with sub-pixel refinement, left-right check and peak ratio.

#include <opencv2/core.hpp>

#include "cairn/perception/stereo/disparity_volume.h"

namespace cairn::perception {

/// Parameters of ComputeWinnerTakeAll().
struct WtaOptions {
  /// Refine the winning disparity by fitting a parabola through its cost and its two neighbours' costs.
  bool subpixel{true};
  /// The left and right winners agree when their integer disparities differ by at most this many pixels.
  int lr_tolerance{1};
  /// Threads splitting the image rows (0 = one per core; rule: cairn::ResolveThreadCount).
  int num_threads{0};
};

/// Per-pixel winner-take-all output; every matrix has the cost volume's size.
struct WtaResult {
  /// CV_32F: winning disparity in pixels (sub-pixel when WtaOptions::subpixel), NaN where no disparity is valid.
  cv::Mat disparity;
  /// CV_32S: index k of the minimum cost (disparity min_disparity + k), -1 where no disparity is valid.
  cv::Mat best_index;
  /// CV_32F: the minimum cost, +infinity where no disparity is valid.
  cv::Mat best_cost;
  /// CV_32F: peak ratio = (smallest other local minimum of the cost curve) / (minimum cost), >= 1; +infinity when
  /// the curve has a single local minimum, 1 when the minimum is zero and shared. Higher means less ambiguous.
  cv::Mat peak_ratio;
  /// CV_32S: winner of the right view (for right column xr, the index k minimising cost(y, xr + d_k, k)), -1 if none.
  cv::Mat right_best_index;
  /// CV_8U: 255 where the left winner and the right winner at x - d agree within WtaOptions::lr_tolerance.
  cv::Mat lr_consistent;
};

/// Computes the winner-take-all disparity of every pixel from `costs`. Infinite costs (disparities pointing
/// outside the right image) never win, nor do NaN costs (a volume filled by hand may hold them), and a NaN
/// neighbour keeps a cost from being a local minimum. `result`'s matrices are reallocated only when their size
/// changes.
void ComputeWinnerTakeAll(const DisparityVolume& costs, const WtaOptions& options, WtaResult* result);

}  // namespace cairn::perception
