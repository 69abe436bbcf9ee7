#include "cairn/perception/stereo/compute_cost_volume.h"

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>
#include <string>
#include <utility>

#include "expect_throws.h"
#include "same_wta_result.h"

namespace cairn::perception {
namespace {

cv::Mat RandomImage(int rows, int cols, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> value(0, 255);
  cv::Mat image(rows, cols, CV_8UC1);
  for (int y = 0; y < rows; ++y)
    for (int x = 0; x < cols; ++x) image.at<uint8_t>(y, x) = static_cast<uint8_t>(value(rng));
  return image;
}

// Direct (slow) window cost with the documented border rule: pixels replicate at the image edges.
double ReferenceCost(const cv::Mat& left, const cv::Mat& right, int y, int x, int d, int window, bool bt) {
  const int r = window / 2;
  auto px = [](const cv::Mat& m, int yy, int xx) {
    return static_cast<double>(m.at<uint8_t>(std::clamp(yy, 0, m.rows - 1), std::clamp(xx, 0, m.cols - 1)));
  };
  double sum = 0.0;
  for (int dy = -r; dy <= r; ++dy) {
    for (int dx = -r; dx <= r; ++dx) {
      const int yy = std::clamp(y + dy, 0, left.rows - 1);
      const int xl = std::clamp(x + dx, 0, left.cols - 1);
      const int xr = std::clamp(xl - d, 0, left.cols - 1);
      const double l = px(left, yy, xl);
      const double rv = px(right, yy, xr);
      if (!bt) {
        sum += (l - rv) * (l - rv);
        continue;
      }
      auto range = [&](const cv::Mat& m, int xx, double* lo, double* hi) {
        const double c = px(m, yy, xx);
        const double a = xx > 0 ? 0.5 * (c + px(m, yy, xx - 1)) : c;
        const double b = xx + 1 < m.cols ? 0.5 * (c + px(m, yy, xx + 1)) : c;
        *lo = std::min({a, b, c});
        *hi = std::max({a, b, c});
      };
      double rlo, rhi, llo, lhi;
      range(right, xr, &rlo, &rhi);
      range(left, xl, &llo, &lhi);
      const double lr = std::max({0.0, l - rhi, rlo - l});
      const double rl = std::max({0.0, rv - lhi, llo - rv});
      sum += std::min(lr, rl);
    }
  }
  return sum;
}

class CostVolumeReferenceTest : public ::testing::TestWithParam<std::tuple<CostFunction, int, int>> {};

TEST_P(CostVolumeReferenceTest, MatchesDirectWindowSums) {
  const auto [cost, window, threads] = GetParam();
  const cv::Mat left = RandomImage(23, 37, 1);
  const cv::Mat right = RandomImage(23, 37, 2);
  CostVolumeOptions options;
  options.cost = cost;
  options.window = window;
  options.min_disparity = -2;
  options.max_disparity = 9;
  options.prefilter = Prefilter::kNone;
  options.num_threads = threads;
  DisparityVolume volume;
  ComputeCostVolume(left, right, options, &volume);
  ASSERT_EQ(volume.num_disparities(), 12);
  for (int y = 0; y < left.rows; ++y) {
    for (int x = 0; x < left.cols; ++x) {
      for (int k = 0; k < 12; ++k) {
        const int d = k - 2;
        if (x - d < 0 || x - d >= left.cols) {
          EXPECT_TRUE(std::isinf(volume.at(y, x, k))) << x << "," << y << " d=" << d;
        } else {
          EXPECT_NEAR(volume.at(y, x, k), ReferenceCost(left, right, y, x, d, window, cost == CostFunction::kBtSad),
                      1e-3)
              << x << "," << y << " d=" << d;
        }
      }
    }
  }
}

INSTANTIATE_TEST_SUITE_P(CostsWindowsThreads, CostVolumeReferenceTest,
                         ::testing::Values(std::make_tuple(CostFunction::kSsd, 1, 1),
                                           std::make_tuple(CostFunction::kSsd, 5, 3),
                                           std::make_tuple(CostFunction::kBtSad, 3, 1),
                                           std::make_tuple(CostFunction::kBtSad, 7, 2)));

TEST(ComputeCostVolumeTest, TrueShiftHasZeroCost) {
  const cv::Mat right = RandomImage(20, 60, 3);
  cv::Mat left(20, 60, CV_8UC1);
  for (int y = 0; y < 20; ++y)
    for (int x = 0; x < 60; ++x) left.at<uint8_t>(y, x) = right.at<uint8_t>(y, std::max(0, x - 4));
  CostVolumeOptions options;
  options.max_disparity = 8;
  options.window = 5;
  DisparityVolume volume;
  ComputeCostVolume(left, right, options, &volume);
  // Away from the left border every window at disparity 4 compares identical pixels.
  for (int y = 0; y < 20; ++y) EXPECT_EQ(volume.at(y, 30, 4), 0.0f);
  EXPECT_GT(volume.at(10, 30, 2), 0.0f);
}

TEST(ComputeCostVolumeTest, SobelPrefilterIsClippedAndCentred) {
  cv::Mat ramp(9, 30, CV_8UC1);
  for (int y = 0; y < 9; ++y)
    for (int x = 0; x < 30; ++x) ramp.at<uint8_t>(y, x) = static_cast<uint8_t>(x < 15 ? 0 : 200);
  const cv::Mat flat = SobelPrefilter(cv::Mat(9, 30, CV_8UC1, cv::Scalar(77)), 9, 31);
  EXPECT_EQ(cv::countNonZero(flat != 31), 0);  // No gradient: the shifted zero.
  const cv::Mat edge = SobelPrefilter(ramp, 9, 31);
  EXPECT_EQ(edge.at<uint8_t>(4, 15), 62);  // A strong rising edge saturates at 2 cap.
  EXPECT_EQ(edge.at<uint8_t>(4, 2), 31);
  CAIRN_EXPECT_THROWS_WITH(SobelPrefilter(ramp, 4, 31), std::invalid_argument, "size 4");
}

// The one-pass cost volume + WTA gives the same bytes as the two calls, for both costs, any thread count and
// disparity ranges that do and do not fill the vector kernels' groups of 8 (negative and single disparities too).
TEST(ComputeCostVolumeTest, OnePassWinnerTakeAllMatchesTheTwoCalls) {
  const cv::Mat left = RandomImage(31, 53, 5);
  const cv::Mat right = RandomImage(31, 53, 6);
  const std::pair<int, int> ranges[] = {{1, 14}, {-3, 12}, {0, 7}, {2, 2}, {0, 40}};
  for (CostFunction cost : {CostFunction::kSsd, CostFunction::kBtSad}) {
    for (int threads : {1, 3}) {
      for (const auto& [dmin, dmax] : ranges) {
        SCOPED_TRACE("threads " + std::to_string(threads) + " range [" + std::to_string(dmin) + ", " +
                     std::to_string(dmax) + "]");
        CostVolumeOptions options;
        options.cost = cost;
        options.window = 5;
        options.min_disparity = dmin;
        options.max_disparity = dmax;
        options.num_threads = threads;
        DisparityVolume separate_costs, fused_costs;
        WtaResult separate, fused;
        ComputeCostVolume(left, right, options, &separate_costs);
        ComputeWinnerTakeAll(separate_costs, WtaOptions{}, &separate);
        ComputeCostVolumeAndWinnerTakeAll(left, right, options, WtaOptions{}, &fused_costs, &fused);
        EXPECT_TRUE(fused_costs.data() == separate_costs.data());
        EXPECT_TRUE(SameWtaResult(fused, separate));
      }
    }
  }
  CostVolumeOptions options;
  options.max_disparity = 14;
  WtaOptions bad;
  bad.lr_tolerance = -2;
  DisparityVolume costs;
  WtaResult wta;
  CAIRN_EXPECT_THROWS_WITH(ComputeCostVolumeAndWinnerTakeAll(left, right, options, bad, &costs, &wta),
                           std::invalid_argument, "lr_tolerance -2");
}

TEST(ComputeCostVolumeTest, RejectsBadInput) {
  DisparityVolume volume;
  CostVolumeOptions options;
  options.max_disparity = 8;
  const cv::Mat a = RandomImage(10, 20, 1);
  CAIRN_EXPECT_THROWS_WITH(ComputeCostVolume(a, RandomImage(10, 21, 1), options, &volume), std::invalid_argument,
                           "20x10", "21x10", "equal size");
  CAIRN_EXPECT_THROWS_WITH(ComputeCostVolume(cv::Mat(), a, options, &volume), std::invalid_argument,
                           "left image is empty");
  cv::Mat floats(10, 20, CV_32F);
  CAIRN_EXPECT_THROWS_WITH(ComputeCostVolume(floats, a, options, &volume), std::invalid_argument, "CV_8UC1");
  options.max_disparity = 25;
  CAIRN_EXPECT_THROWS_WITH(ComputeCostVolume(a, a, options, &volume), std::invalid_argument, "wider than the image");
}

}  // namespace
}  // namespace cairn::perception
