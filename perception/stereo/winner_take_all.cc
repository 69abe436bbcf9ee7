#include "cairn/perception/stereo/winner_take_all.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "cairn/common/cairn_assert.h"
#include "cairn/common/parallel_for.h"
#include "cairn/perception/internal/multiversion.h"
#include "cairn/perception/stereo/internal/winner_take_all_row.h"

namespace cairn::perception {

namespace {

constexpr float kInf = std::numeric_limits<float>::infinity();

// min(init, f(begin), ..., f(end - 1)) over eight independent lanes, so that the compiler keeps the reduction in
// vector registers (GCC left `#pragma omp simd reduction(min)` loops scalar in the AVX2 clone). The minimum is
// exact, so the lane order does not change the result.
template <typename T, typename F>
inline T LaneMin(int begin, int end, T init, const F& f) {
  constexpr int kLanes = 8;
  T lane[kLanes];
  for (int l = 0; l < kLanes; ++l) lane[l] = init;
  int k = begin;
  for (; k + kLanes <= end; k += kLanes) {
    for (int l = 0; l < kLanes; ++l) lane[l] = std::min(lane[l], f(k + l));
  }
  for (; k < end; ++k) lane[0] = std::min(lane[0], f(k));
  T m = init;
  for (int l = 0; l < kLanes; ++l) m = std::min(m, lane[l]);
  return m;
}

// One row of the cost volume (`width` curves of `num_disp` costs, pixel-major). Every pass over a curve is a
// branch-free loop that GCC vectorises (element-wise selects, LaneMin() reductions); the row kernel is compiled
// for AVX2 and baseline x86-64.
//
// The right view is kept in reversed column order: slot i holds right column xr = width - 1 - i, so the left
// column x at disparity index k updates slot width - 1 - x + dmin + k, consecutive in k, and the update is a
// contiguous select instead of a gather.
CAIRN_MULTIVERSION
void WtaRowKernel(const float* row, int width, int num_disp, int dmin, bool subpixel, int lr_tolerance,
                  float* right_value, int32_t* right_index, float* disparity, int32_t* best_index, float* best_cost,
                  float* peak_ratio, int32_t* right_best, uint8_t* consistent) {
  constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
  std::vector<float> local_minima(num_disp);
  float* local = local_minima.data();
  std::fill(right_value, right_value + width, kInf);
  std::fill(right_index, right_index + width, -1);
  for (int x = 0; x < width; ++x) {
    const float* c = row + static_cast<std::size_t>(x) * num_disp;
    // Right view: column xr = x - dmin - k is matched by this left column at disparity index k. Visiting left
    // columns in order presents the k of a given xr in increasing order, so the strict comparison resolves ties to
    // the smallest k, as a per-column scan would.
    const int k_begin = std::max(0, x - (width - 1) - dmin);
    const int k_end = std::min(num_disp, x - dmin + 1);
    if (k_begin < k_end) {
      float* value = right_value + (width - 1 - x + dmin + k_begin);
      int32_t* index = right_index + (width - 1 - x + dmin + k_begin);
      const float* curve = c + k_begin;
      const int n = k_end - k_begin;
#pragma omp simd
      for (int j = 0; j < n; ++j) {
        const bool better = curve[j] < value[j];
        index[j] = better ? k_begin + j : index[j];
        value[j] = better ? curve[j] : value[j];
      }
    }
    // The minimum, then its first index, both as vector reductions.
    const float best_value = LaneMin(0, num_disp, kInf, [c](int k) { return c[k]; });
    int best = LaneMin(0, num_disp, num_disp, [c, best_value, num_disp](int k) {
      return c[k] == best_value ? k : num_disp;
    });
    if (!(best_value < kInf)) best = -1;
    best_index[x] = best;
    best_cost[x] = best >= 0 ? c[best] : best_value;  // the zero at the first index if +0 and -0 both occur
    if (best < 0) {
      disparity[x] = kNaN;
      peak_ratio[x] = kInf;
      continue;
    }
    // Second-best local minimum: a cost no larger than its neighbours, other than the winner (infinite costs never
    // win the minimum, so they need no test).
    float second = kInf;
    if (num_disp > 1) {
      if (best != 0 && c[0] <= c[1]) second = c[0];
      if (best != num_disp - 1 && c[num_disp - 1] <= c[num_disp - 2]) second = std::min(second, c[num_disp - 1]);
    }
    // Interior local minima (their cost, +infinity elsewhere) in one element-wise pass, then their minimum left
    // and right of the winner: two reductions, so the winner needs no test per element.
    for (int k = 1; k < num_disp - 1; ++k) {
      const float v = c[k];
      local[k] = ((v <= c[k - 1]) & (v <= c[k + 1])) ? v : kInf;  // a NaN neighbour fails its comparison
    }
    second = LaneMin(1, std::max(1, best), second, [local](int k) { return local[k]; });
    second = LaneMin(std::max(1, best + 1), num_disp - 1, second, [local](int k) { return local[k]; });
    if (!std::isfinite(second)) {
      peak_ratio[x] = kInf;
    } else if (best_value > 0.0f) {
      peak_ratio[x] = second / best_value;
    } else {
      peak_ratio[x] = second > 0.0f ? kInf : 1.0f;
    }
    float offset = 0.0f;
    if (subpixel && best > 0 && best < num_disp - 1 && std::isfinite(c[best - 1]) && std::isfinite(c[best + 1])) {
      const float denominator = c[best - 1] - 2.0f * c[best] + c[best + 1];
      if (denominator > 0.0f) offset = std::clamp(0.5f * (c[best - 1] - c[best + 1]) / denominator, -0.5f, 0.5f);
    }
    disparity[x] = static_cast<float>(dmin + best) + offset;
  }
  internal::LeftRightCheckRow(width, dmin, lr_tolerance, right_index, best_index, right_best, consistent);
}

}  // namespace

namespace internal {

void AllocateWtaResult(int height, int width, WtaResult* result) {
  result->disparity.create(height, width, CV_32F);
  result->best_index.create(height, width, CV_32S);
  result->best_cost.create(height, width, CV_32F);
  result->peak_ratio.create(height, width, CV_32F);
  result->right_best_index.create(height, width, CV_32S);
  result->lr_consistent.create(height, width, CV_8U);
}

void LeftRightCheckRow(int width, int dmin, int lr_tolerance, const int32_t* reversed_right_index,
                       const int32_t* best_index, int32_t* right_best, uint8_t* consistent) {
  for (int xr = 0; xr < width; ++xr) right_best[xr] = reversed_right_index[width - 1 - xr];
  for (int x = 0; x < width; ++x) {
    consistent[x] = 0;
    const int k = best_index[x];
    if (k < 0) continue;
    const int xr = x - (dmin + k);
    if (xr < 0 || xr >= width) continue;
    if (right_best[xr] >= 0 && std::abs(right_best[xr] - k) <= lr_tolerance) consistent[x] = 255;
  }
}

void WinnerTakeAllRow(const float* row, int width, int num_disp, int dmin, const WtaOptions& options, int y,
                      float* right_value, int32_t* right_index, WtaResult* result) {
  WtaRowKernel(row, width, num_disp, dmin, options.subpixel, options.lr_tolerance, right_value, right_index,
               result->disparity.ptr<float>(y), result->best_index.ptr<int32_t>(y), result->best_cost.ptr<float>(y),
               result->peak_ratio.ptr<float>(y), result->right_best_index.ptr<int32_t>(y),
               result->lr_consistent.ptr<uint8_t>(y));
}

}  // namespace internal

void ComputeWinnerTakeAll(const DisparityVolume& costs, const WtaOptions& options, WtaResult* result) {
  CAIRN_CHECK(result != nullptr);
  if (costs.num_disparities() == 0) {
    throw std::invalid_argument("ComputeWinnerTakeAll: the cost volume is empty; run ComputeCostVolume() first");
  }
  internal::ValidateWtaOptions(options);
  const int height = costs.height();
  const int width = costs.width();
  internal::AllocateWtaResult(height, width, result);
  // Rows are independent; each thread keeps its own right-view scratch row.
  const int num_disp = costs.num_disparities();
  const int dmin = costs.min_disparity();
  const bool avx2 = internal::CpuHasAvx2();
  ParallelFor(height, options.num_threads, [&](int, int y0, int y1) {
    if (avx2) {
      internal::WtaRowScratch scratch;
      scratch.Resize(width, num_disp, dmin);
      for (int y = y0; y < y1; ++y) {
        internal::WinnerTakeAllRowAvx2(costs.curve(y, 0), width, num_disp, dmin, options, y, &scratch, result);
      }
      return;
    }
    std::vector<float> right_value(width);
    std::vector<int32_t> right_index(width);
    for (int y = y0; y < y1; ++y) {
      internal::WinnerTakeAllRow(costs.curve(y, 0), width, num_disp, dmin, options, y, right_value.data(),
                                 right_index.data(), result);
    }
  });
}

}  // namespace cairn::perception
