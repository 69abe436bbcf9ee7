#include "cairn/perception/stereo/winner_take_all.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <random>
#include <stdexcept>
#include <vector>

#include "cairn/perception/stereo/compute_cost_volume.h"
#include "expect_throws.h"

namespace cairn::perception {
namespace {

TEST(WinnerTakeAllTest, SubpixelPeakRatioAndInvalidPixels) {
  DisparityVolume costs(1, 2, 0, 5);
  const float curve[6] = {9.0f, 4.0f, 1.0f, 3.0f, 2.0f, 8.0f};  // minimum at 2, other local minimum 2 at k=4
  std::copy(curve, curve + 6, costs.mutable_curve(0, 0));
  for (int k = 0; k < 6; ++k) costs.mutable_curve(0, 1)[k] = std::numeric_limits<float>::infinity();
  WtaResult result;
  ComputeWinnerTakeAll(costs, WtaOptions{}, &result);
  EXPECT_EQ(result.best_index.at<int32_t>(0, 0), 2);
  EXPECT_FLOAT_EQ(result.best_cost.at<float>(0, 0), 1.0f);
  // Parabola through (1,4), (2,1), (3,3): vertex at 2 + (4 - 3) / (2 * 5) = 2.1.
  EXPECT_NEAR(result.disparity.at<float>(0, 0), 2.1f, 1e-6);
  EXPECT_FLOAT_EQ(result.peak_ratio.at<float>(0, 0), 2.0f);
  EXPECT_EQ(result.best_index.at<int32_t>(0, 1), -1);
  EXPECT_TRUE(std::isnan(result.disparity.at<float>(0, 1)));
}

TEST(WinnerTakeAllTest, RecoversAShiftAndChecksLeftRight) {
  std::mt19937 rng(7);
  std::uniform_int_distribution<int> value(0, 255);
  cv::Mat right(30, 80, CV_8UC1);
  for (int y = 0; y < 30; ++y)
    for (int x = 0; x < 80; ++x) right.at<uint8_t>(y, x) = static_cast<uint8_t>(value(rng));
  cv::Mat left(30, 80, CV_8UC1);
  for (int y = 0; y < 30; ++y)
    for (int x = 0; x < 80; ++x) left.at<uint8_t>(y, x) = right.at<uint8_t>(y, std::max(0, x - 6));
  CostVolumeOptions options;
  options.max_disparity = 15;
  options.window = 5;
  options.prefilter = Prefilter::kNone;
  DisparityVolume costs;
  ComputeCostVolume(left, right, options, &costs);
  WtaResult result;
  ComputeWinnerTakeAll(costs, WtaOptions{}, &result);
  int consistent = 0;
  for (int y = 3; y < 27; ++y) {
    for (int x = 20; x < 75; ++x) {
      EXPECT_EQ(result.best_index.at<int32_t>(y, x), 6);
      EXPECT_NEAR(result.disparity.at<float>(y, x), 6.0f, 0.5f);
      consistent += result.lr_consistent.at<uint8_t>(y, x) != 0 ? 1 : 0;
    }
  }
  EXPECT_EQ(consistent, 24 * 55);
  WtaOptions bad;
  bad.lr_tolerance = -1;
  CAIRN_EXPECT_THROWS_WITH(ComputeWinnerTakeAll(costs, bad, &result), std::invalid_argument, "lr_tolerance -1");
}

// The vectorised kernel against a plain per-pixel scan: small integer costs (many ties), infinite costs where
// the right column falls outside the image, every output compared exactly, for 1 and 3 threads.
TEST(WinnerTakeAllTest, MatchesAPlainScanWithTiesAndInfiniteCosts) {
  constexpr float kInf = std::numeric_limits<float>::infinity();
  const int height = 5, width = 37, dmin = 2, dmax = 12, num_disp = dmax - dmin + 1;
  DisparityVolume costs(height, width, dmin, dmax);
  std::mt19937 rng(3);
  std::uniform_int_distribution<int> value(0, 6);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x)
      for (int k = 0; k < num_disp; ++k) {
        const int xr = x - (dmin + k);
        costs.mutable_curve(y, x)[k] = xr < 0 ? kInf : static_cast<float>(value(rng));
      }
  for (int threads : {1, 3}) {
    WtaOptions options;
    options.num_threads = threads;
    WtaResult result;
    ComputeWinnerTakeAll(costs, options, &result);
    for (int y = 0; y < height; ++y) {
      std::vector<int> right_best(width, -1);
      for (int xr = 0; xr < width; ++xr) {
        float best = kInf;
        for (int k = 0; k < num_disp; ++k) {
          const int x = xr + dmin + k;
          if (x < width && costs.at(y, x, k) < best) {
            best = costs.at(y, x, k);
            right_best[xr] = k;
          }
        }
        EXPECT_EQ(result.right_best_index.at<int32_t>(y, xr), right_best[xr]) << "y " << y << " xr " << xr;
      }
      for (int x = 0; x < width; ++x) {
        const float* c = costs.curve(y, x);
        int best = -1;
        for (int k = 0; k < num_disp; ++k)
          if (c[k] < kInf && (best < 0 || c[k] < c[best])) best = k;
        ASSERT_EQ(result.best_index.at<int32_t>(y, x), best) << "y " << y << " x " << x;
        if (best < 0) continue;
        float second = kInf;
        for (int k = 0; k < num_disp; ++k) {
          const bool local = (k == 0 || c[k] <= c[k - 1]) && (k == num_disp - 1 || c[k] <= c[k + 1]);
          if (k != best && local) second = std::min(second, c[k]);
        }
        const float ratio = second == kInf ? kInf : c[best] > 0.0f ? second / c[best] : second > 0.0f ? kInf : 1.0f;
        EXPECT_EQ(result.peak_ratio.at<float>(y, x), ratio) << "y " << y << " x " << x;
        EXPECT_EQ(result.best_cost.at<float>(y, x), c[best]);
        const int xr = x - (dmin + best);
        const bool consistent = xr >= 0 && right_best[xr] >= 0 && std::abs(right_best[xr] - best) <= 1;
        EXPECT_EQ(result.lr_consistent.at<uint8_t>(y, x) != 0, consistent) << "y " << y << " x " << x;
      }
    }
  }
}

// The thread count follows cairn::ResolveThreadCount (test/common/parallel_for_test.cc); -1 once meant "all cores".
TEST(WinnerTakeAllTest, ANegativeThreadCountIsAnError) {
  DisparityVolume costs(2, 4, 0, 1);
  WtaOptions options;
  options.num_threads = -1;
  WtaResult result;
  CAIRN_EXPECT_THROWS_WITH(ComputeWinnerTakeAll(costs, options, &result), std::invalid_argument,
                           "num_threads -1 is negative");
}

}  // namespace
}  // namespace cairn::perception
