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
#include "cairn/perception/internal/parallel_rows.h"

namespace cairn::perception {

void ComputeWinnerTakeAll(const DisparityVolume& costs, const WtaOptions& options, WtaResult* result) {
  CAIRN_CHECK(result != nullptr);
  if (costs.num_disparities() == 0) {
    throw std::invalid_argument("ComputeWinnerTakeAll: the cost volume is empty; run ComputeCostVolume() first");
  }
  if (options.lr_tolerance < 0) {
    throw std::invalid_argument("WtaOptions::lr_tolerance " + std::to_string(options.lr_tolerance) +
                                " is negative; use 0 (exact) or 1 (the usual tolerance)");
  }
  const int height = costs.height();
  const int width = costs.width();
  const int num_disp = costs.num_disparities();
  const int dmin = costs.min_disparity();
  constexpr float kInf = std::numeric_limits<float>::infinity();
  constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
  result->disparity.create(height, width, CV_32F);
  result->best_index.create(height, width, CV_32S);
  result->best_cost.create(height, width, CV_32F);
  result->peak_ratio.create(height, width, CV_32F);
  result->right_best_index.create(height, width, CV_32S);
  result->lr_consistent.create(height, width, CV_8U);

  // Rows are independent; each thread keeps its own right-view scratch row.
  internal::ParallelForRows(height, internal::ResolveThreadCount(options.num_threads), [&](int, int y0, int y1) {
    std::vector<float> right_value(width);
    for (int y = y0; y < y1; ++y) {
      float* disparity = result->disparity.ptr<float>(y);
      int32_t* best_index = result->best_index.ptr<int32_t>(y);
      float* best_cost = result->best_cost.ptr<float>(y);
      float* peak_ratio = result->peak_ratio.ptr<float>(y);
      int32_t* right_best = result->right_best_index.ptr<int32_t>(y);
      std::fill(right_value.begin(), right_value.end(), kInf);
      std::fill(right_best, right_best + width, -1);
      for (int x = 0; x < width; ++x) {
        const float* c = costs.curve(y, x);
        // Right view: column xr = x - d_k is matched by this left column at disparity k. Visiting left columns in
        // order reads each curve once, contiguously (the volume is x-major, k fastest), and presents the k of a
        // given xr in increasing order, so ties resolve to the smallest k as in a per-column scan.
        const int k_begin = std::max(0, x - (width - 1) - dmin);
        const int k_end = std::min(num_disp, x - dmin + 1);
        // Each k touches a different xr, so the iterations are independent and vectorise (as selects).
        if (k_begin < k_end) {
          // value_at[-j] and best_at[-j] belong to column xr = x - dmin - (k_begin + j).
          float* value_at = right_value.data() + (x - dmin - k_begin);
          int32_t* best_at = right_best + (x - dmin - k_begin);
          const float* curve = c + k_begin;
#pragma omp simd
          for (int j = 0; j < k_end - k_begin; ++j) {
            const bool better = curve[j] < value_at[-j];
            best_at[-j] = better ? k_begin + j : best_at[-j];
            value_at[-j] = better ? curve[j] : value_at[-j];
          }
        }
        // Branch-free passes so that the compiler vectorises them (OpenMP SIMD reductions, -fopenmp-simd): the
        // minimum, then its first index.
        float best_value = kInf;
#pragma omp simd reduction(min : best_value)
        for (int k = 0; k < num_disp; ++k) best_value = std::min(best_value, c[k]);
        int best = -1;
        if (best_value < kInf) {
          best = 0;
          while (c[best] != best_value) ++best;
        }
        best_index[x] = best;
        best_cost[x] = best_value;
        if (best < 0) {
          disparity[x] = kNaN;
          peak_ratio[x] = kInf;
          continue;
        }
        // Second-best local minimum: a cost no larger than its neighbours, other than the winner (infinite costs
        // never win the minimum, so they need no test).
        float second = kInf;
        if (num_disp > 1) {
          if (best != 0 && c[0] <= c[1]) second = c[0];
          if (best != num_disp - 1 && c[num_disp - 1] <= c[num_disp - 2]) second = std::min(second, c[num_disp - 1]);
        }
        // Interior local minima left and right of the winner: two loops, so the winner needs no test per element.
        auto local_min = [c](int begin, int end, float init) {
          constexpr float kNone = std::numeric_limits<float>::infinity();
          float m = init;
#pragma omp simd reduction(min : m)
          for (int k = begin; k < end; ++k) {
            const float v = c[k];
            m = std::min(m, v <= std::min(c[k - 1], c[k + 1]) ? v : kNone);
          }
          return m;
        };
        second = local_min(1, std::max(1, best), second);
        second = local_min(std::max(1, best + 1), num_disp - 1, second);
        if (!std::isfinite(second)) {
          peak_ratio[x] = kInf;
        } else if (best_value > 0.0f) {
          peak_ratio[x] = second / best_value;
        } else {
          peak_ratio[x] = second > 0.0f ? kInf : 1.0f;
        }
        float offset = 0.0f;
        if (options.subpixel && best > 0 && best < num_disp - 1 && std::isfinite(c[best - 1]) &&
            std::isfinite(c[best + 1])) {
          const float denominator = c[best - 1] - 2.0f * c[best] + c[best + 1];
          if (denominator > 0.0f) offset = std::clamp(0.5f * (c[best - 1] - c[best + 1]) / denominator, -0.5f, 0.5f);
        }
        disparity[x] = static_cast<float>(dmin + best) + offset;
      }
      uint8_t* consistent = result->lr_consistent.ptr<uint8_t>(y);
      for (int x = 0; x < width; ++x) {
        consistent[x] = 0;
        const int k = best_index[x];
        if (k < 0) continue;
        const int xr = x - (dmin + k);
        if (xr < 0 || xr >= width) continue;
        if (right_best[xr] >= 0 && std::abs(right_best[xr] - k) <= options.lr_tolerance) consistent[x] = 255;
      }
    }
  });
}

}  // namespace cairn::perception
