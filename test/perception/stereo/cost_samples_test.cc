#include "cairn/perception/stereo/cost_samples.h"

#include <limits>
#include <stdexcept>

#include "expect_throws.h"

namespace cairn::perception {
namespace {

TEST(CostSamplesTest, CollectsConsistentWinnersAndGroundTruthCosts) {
  DisparityVolume costs(1, 3, 0, 2);
  for (int x = 0; x < 3; ++x)
    for (int k = 0; k < 3; ++k) costs.mutable_curve(0, x)[k] = static_cast<float>(10 * x + k);
  WtaResult wta;
  wta.best_cost = (cv::Mat_<float>(1, 3) << 1.0f, 2.0f, 3.0f);
  wta.lr_consistent = (cv::Mat_<uint8_t>(1, 3) << 255, 0, 255);
  std::vector<float> samples;
  EXPECT_EQ(CollectConsistentWtaCosts(costs, wta, &samples), 2u);
  EXPECT_EQ(samples, (std::vector<float>{1.0f, 3.0f}));
  const cv::Mat gt = (cv::Mat_<float>(1, 3) << 0.0f, 1.2f, 5.0f);  // unknown, d=1, out of range
  samples.clear();
  EXPECT_EQ(CollectGroundTruthCosts(costs, gt, cv::Mat(), &samples), 1u);
  EXPECT_EQ(samples, (std::vector<float>{11.0f}));
  CAIRN_EXPECT_THROWS_WITH(CollectGroundTruthCosts(costs, cv::Mat(2, 3, CV_32F), cv::Mat(), &samples),
                           std::invalid_argument, "3x2", "LoadDisparityImage");
  // An infinite true disparity is skipped, not rounded out of range.
  const cv::Mat far = (cv::Mat_<float>(1, 3) << std::numeric_limits<float>::infinity(), 1.2f, 0.0f);
  samples.clear();
  EXPECT_EQ(CollectGroundTruthCosts(costs, far, cv::Mat(), &samples), 1u);
  // A result without its left-right matrix used to be read through a null row pointer.
  WtaResult partial;
  partial.best_cost = wta.best_cost;
  CAIRN_EXPECT_THROWS_WITH(CollectConsistentWtaCosts(costs, partial, &samples), std::invalid_argument,
                           "lacks its cost or left-right matrices");
}

}  // namespace
}  // namespace cairn::perception
