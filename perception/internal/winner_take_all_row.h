#pragma once

/// @file
/// Internal: one image row of ComputeWinnerTakeAll(), shared with ComputeCostVolumeAndWinnerTakeAll(), which runs
/// it on each row of costs while the row is still in cache. Not part of the installed API.

#include <cstdint>
#include <stdexcept>
#include <string>

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

}  // namespace cairn::perception::internal
