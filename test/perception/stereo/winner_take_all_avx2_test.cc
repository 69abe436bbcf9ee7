// The winner-take-all kernel ComputeWinnerTakeAll() dispatches to (AVX2 where available) against the portable
// row kernel, on curves built to stress the vector code: many ties (small integer costs), infinite and NaN costs
// anywhere, +0 and -0, disparity counts that do and do not fill groups of 8, and negative disparities.

#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "cairn/perception/stereo/disparity_volume.h"
#include "cairn/perception/stereo/internal/winner_take_all_row.h"
#include "same_wta_result.h"

namespace cairn::perception {
namespace {

TEST(WinnerTakeAllAvx2Test, DispatchedKernelMatchesThePortableKernelByteForByte) {
  constexpr float kInf = std::numeric_limits<float>::infinity();
  const int height = 4, width = 45;
  std::mt19937 rng(11);
  std::uniform_int_distribution<int> value(0, 5);
  std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
  for (const auto& [dmin, dmax] : {std::pair{2, 12}, std::pair{-4, 11}, std::pair{0, 0}, std::pair{1, 8},
                                   std::pair{3, 30}, std::pair{-7, 1}}) {
    for (const bool subpixel : {true, false}) {
      SCOPED_TRACE("range [" + std::to_string(dmin) + ", " + std::to_string(dmax) + "] subpixel " +
                   std::to_string(subpixel));
      const int num_disp = dmax - dmin + 1;
      DisparityVolume costs(height, width, dmin, dmax);
      for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x)
          for (int k = 0; k < num_disp; ++k) {
            const int xr = x - (dmin + k);
            const bool outside = xr < 0 || xr >= width;
            // Mostly ties, some real-valued costs (sub-pixel offsets), some stray infinities and NaNs inside the
            // image (a user's volume may hold anything), and negative zeros tying with positive ones.
            float c = uniform(rng) < 0.2f ? value(rng) + uniform(rng) : static_cast<float>(value(rng));
            const float draw = uniform(rng);
            if (draw < 0.05f) c = kInf;
            if (draw > 0.95f) c = std::numeric_limits<float>::quiet_NaN();
            if (c == 0.0f && uniform(rng) < 0.5f) c = -0.0f;
            costs.mutable_curve(y, x)[k] = outside ? kInf : c;
          }
      WtaOptions options;
      options.subpixel = subpixel;
      WtaResult portable, dispatched;
      internal::AllocateWtaResult(height, width, &portable);
      std::vector<float> right_value(width);
      std::vector<int32_t> right_index(width);
      for (int y = 0; y < height; ++y) {
        internal::WinnerTakeAllRow(costs.curve(y, 0), width, num_disp, dmin, options, y, right_value.data(),
                                   right_index.data(), &portable);
      }
      // ComputeWinnerTakeAll() runs the AVX2 kernel where the processor has it (the portable one elsewhere, which
      // this then compares with itself).
      ComputeWinnerTakeAll(costs, options, &dispatched);
      EXPECT_TRUE(SameWtaResult(dispatched, portable));
      // The test must exercise what it claims: ties, rejected pixels and left-right disagreements all occur.
      EXPECT_GT(cv::countNonZero(portable.lr_consistent), 0);
      if (num_disp > 1) {
        EXPECT_LT(cv::countNonZero(portable.lr_consistent), height * width);
      }
    }
  }
}

}  // namespace
}  // namespace cairn::perception
