#include "cairn/perception/stereo/winner_take_all.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <limits>
#include <stdexcept>
#include <string>

#include "cairn/common/cairn_assert.h"

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

  for (int y = 0; y < height; ++y) {
    float* disparity = result->disparity.ptr<float>(y);
    int32_t* best_index = result->best_index.ptr<int32_t>(y);
    float* best_cost = result->best_cost.ptr<float>(y);
    float* peak_ratio = result->peak_ratio.ptr<float>(y);
    for (int x = 0; x < width; ++x) {
      const float* c = costs.curve(y, x);
      int best = -1;
      float best_value = kInf;
      for (int k = 0; k < num_disp; ++k) {
        if (c[k] < best_value) {
          best_value = c[k];
          best = k;
        }
      }
      best_index[x] = best;
      best_cost[x] = best_value;
      if (best < 0) {
        disparity[x] = kNaN;
        peak_ratio[x] = kInf;
        continue;
      }
      // Second-best local minimum: a finite cost no larger than its finite neighbours, other than the winner.
      float second = kInf;
      for (int k = 0; k < num_disp; ++k) {
        if (k == best || !std::isfinite(c[k])) continue;
        const bool left_ok = k == 0 || !(c[k - 1] < c[k]);
        const bool right_ok = k == num_disp - 1 || !(c[k + 1] < c[k]);
        if (left_ok && right_ok && c[k] < second) second = c[k];
      }
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
    // Right view: column xr matches left column xr + d.
    int32_t* right_best = result->right_best_index.ptr<int32_t>(y);
    for (int xr = 0; xr < width; ++xr) {
      int best = -1;
      float best_value = kInf;
      for (int k = 0; k < num_disp; ++k) {
        const int x = xr + dmin + k;
        if (x < 0 || x >= width) continue;
        const float value = costs.at(y, x, k);
        if (value < best_value) {
          best_value = value;
          best = k;
        }
      }
      right_best[xr] = best;
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
}

}  // namespace cairn::perception
