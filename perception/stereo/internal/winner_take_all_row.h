#pragma once

/// @file
/// Internal: one image row of ComputeWinnerTakeAll(), shared with ComputeCostVolumeAndWinnerTakeAll(), which runs
/// it on each row of costs while the row is still in cache. Not part of the installed API.

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "cairn/perception/stereo/winner_take_all.h"

namespace cairn::perception::internal {

/// Throws std::invalid_argument for options ComputeWinnerTakeAll() rejects.
inline void ValidateWtaOptions(const WtaOptions& options) {
  if (options.lr_tolerance < 0) {
    throw std::invalid_argument("WtaOptions::lr_tolerance " + std::to_string(options.lr_tolerance) +
                                " is negative; use 0 (exact) or 1 (the usual tolerance)");
  }
}

/// Sizes `result`'s matrices for a height x width image (reallocating only when the size changes).
void AllocateWtaResult(int height, int width, WtaResult* result);

/// Winner-take-all of image row y: `row` holds the row's `width` curves of `num_disp` costs (pixel-major, as in
/// DisparityVolume), disparity index k meaning disparity dmin + k. Writes row y of every matrix of `result`
/// (allocated by AllocateWtaResult()). `right_value` and `right_index` are scratch of `width` elements each.
void WinnerTakeAllRow(const float* row, int width, int num_disp, int dmin, const WtaOptions& options, int y,
                      float* right_value, int32_t* right_index, WtaResult* result);

/// The end of a row's winner-take-all: the right view's winners in image order (`reversed_right_index` holds the
/// winner of right column xr at width - 1 - xr) and the left-right check of every left winner.
void LeftRightCheckRow(int width, int dmin, int lr_tolerance, const int32_t* reversed_right_index,
                       const int32_t* best_index, int32_t* right_best, uint8_t* consistent);

/// True when the CPU can run the AVX2 kernels below (checked once). Callers fall back to the portable kernels
/// otherwise; both give identical results (winner_take_all_avx2_test).
bool CpuHasAvx2();

/// Per-thread scratch of the AVX2 kernels, sized for one image width and disparity range by Resize().
struct WtaRowScratch {
  WtaRowScratch() = default;
  // `curve` points into `curve_storage`: a copy would point into the original.
  WtaRowScratch(const WtaRowScratch&) = delete;
  WtaRowScratch& operator=(const WtaRowScratch&) = delete;

  void Resize(int width, int num_disp, int dmin);

  int chunks{0};  ///< groups of 8 disparities, the last one padded
  int shift{0};   ///< offset of the right-view slots, so that a negative min disparity indexes from 0
  float* curve{nullptr};  ///< 32-byte aligned; curve[-1] and curve[num_disp, 8 chunks) are +infinity
  std::vector<float> curve_storage;
  std::vector<float> right_value;   ///< right view: the smallest cost so far per right column (reversed order)
  std::vector<int32_t> right_index;  ///< and its disparity index
  std::vector<int32_t> acc;          ///< horizontal running sums of the fused kernel
};

/// WinnerTakeAllRow() with AVX2: one pass per pixel over its curve, copied into the scratch's padded buffer.
/// Requires CpuHasAvx2() and a scratch sized for (width, num_disp, dmin).
void WinnerTakeAllRowAvx2(const float* row, int width, int num_disp, int dmin, const WtaOptions& options, int y,
                          WtaRowScratch* scratch, WtaResult* result);

/// The last stage of ComputeCostVolumeAndWinnerTakeAll() for image row y with AVX2: the horizontal running sum
/// of `colsum` (width columns of num_disp vertical window sums) over 2 radius + 1 columns (edges replicated),
/// times `scale`, +infinity where the right column falls outside the image, written to `costs` (the row's
/// width x num_disp costs), and each pixel's winner-take-all while its curve is in registers. Same results as the
/// portable aggregation followed by WinnerTakeAllRow(). Requires CpuHasAvx2() and a sized scratch.
void AggregateRowAndWinnerTakeAllAvx2(const int32_t* colsum, int width, int num_disp, int dmin, int radius,
                                      float scale, const WtaOptions& options, int y, WtaRowScratch* scratch,
                                      float* costs, WtaResult* result);

}  // namespace cairn::perception::internal
