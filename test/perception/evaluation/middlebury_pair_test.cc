#include "cairn/perception/evaluation/middlebury_pair.h"

#include <stdexcept>

#include "expect_throws.h"

namespace cairn::perception {
namespace {

const std::string kData = std::string(CAIRN_SHARED_DIR) + "/data/middlebury";

TEST(MiddleburyPairTest, LoadsVenusWithOcclusions) {
  const auto pair = MiddleburyPair::Load(kData + "/venus", 8.0);
  EXPECT_EQ(pair.left.size(), cv::Size(434, 383));
  EXPECT_EQ(pair.left.type(), CV_8UC1);
  double lo = 0.0, hi = 0.0;
  cv::minMaxLoc(pair.gt_left, &lo, &hi);
  EXPECT_GT(hi, 15.0);  // venus spans about 3..20 px
  EXPECT_LT(hi, 25.0);
  const int occluded = cv::countNonZero(pair.occluded);
  EXPECT_GT(occluded, 100);
  EXPECT_LT(occluded, pair.left.total() / 10);
}

TEST(MiddleburyPairTest, TsukubaHasNoRightGroundTruth) {
  const auto pair = MiddleburyPair::Load(kData + "/tsukuba", 16.0);
  EXPECT_TRUE(pair.gt_right.empty());
  EXPECT_TRUE(pair.occluded.empty());
}

TEST(MiddleburyPairTest, MissingFilesAndBadScalesAreNamed) {
  CAIRN_EXPECT_THROWS_WITH(MiddleburyPair::Load(kData + "/nowhere", 8.0), std::runtime_error, "nowhere/im2.png",
                           "check the path");
  CAIRN_EXPECT_THROWS_WITH(LoadDisparityImage(kData + "/venus/disp2.png", 0.0), std::invalid_argument, "scale 0");
  const cv::Mat a(3, 4, CV_32F, cv::Scalar(1.0f));
  CAIRN_EXPECT_THROWS_WITH(OcclusionFromGroundTruth(a, cv::Mat(3, 5, CV_32F)), std::invalid_argument, "4x3", "5x3");
}

}  // namespace
}  // namespace cairn::perception
