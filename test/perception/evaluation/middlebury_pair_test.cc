#include "cairn/perception/evaluation/middlebury_pair.h"

#include <limits>
#include <stdexcept>
#include <string>

#include <opencv2/imgcodecs.hpp>

#include "expect_throws.h"
#include "test_paths.h"

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

// KITTI stores disparity * 256 in 16-bit PNGs (0 = invalid). Reading such a file as 8-bit keeps only the high
// byte: 40.5 px became 40 / 256 = 0.16 px, and every pixel looked bad (a bad-pixel rate of 0.997).
TEST(MiddleburyPairTest, ReadsSixteenBitGroundTruthAtFullDepth) {
  cv::Mat values(3, 5, CV_16UC1, cv::Scalar(0));
  values.at<uint16_t>(0, 1) = static_cast<uint16_t>(40.5 * 256);
  values.at<uint16_t>(2, 4) = 65535;
  values.at<uint16_t>(1, 2) = 1;
  const std::string path = testing::TempDir() + "middlebury_pair_test_kitti.png";
  ASSERT_TRUE(cv::imwrite(path, values));
  for (const cv::Mat& disparity : {LoadDisparityImage(path, kKittiDisparityScale), LoadDisparityImage(path)}) {
    ASSERT_EQ(disparity.type(), CV_32FC1);
    EXPECT_FLOAT_EQ(disparity.at<float>(0, 1), 40.5f);
    EXPECT_FLOAT_EQ(disparity.at<float>(2, 4), 65535.0f / 256.0f);
    EXPECT_FLOAT_EQ(disparity.at<float>(1, 2), 1.0f / 256.0f);
    EXPECT_FLOAT_EQ(disparity.at<float>(0, 0), 0.0f);  // invalid stays unknown
  }
  // An 8-bit Middlebury map (grey in three channels) keeps its scale; without one it cannot be read.
  const cv::Mat venus = LoadDisparityImage(kData + "/venus/disp2.png", 8.0);
  double hi = 0.0;
  cv::minMaxLoc(venus, nullptr, &hi);
  EXPECT_NEAR(hi, 19.75, 1.0);
  CAIRN_EXPECT_THROWS_WITH(LoadDisparityImage(kData + "/venus/disp2.png"), std::invalid_argument, "8-bit",
                           "Middlebury 2001: 8");
  // A colour visualisation of a disparity map is not a disparity map.
  cv::Mat colour(3, 5, CV_8UC3, cv::Scalar(10, 20, 30));
  const std::string colour_path = testing::TempDir() + "middlebury_pair_test_colour.png";
  ASSERT_TRUE(cv::imwrite(colour_path, colour));
  CAIRN_EXPECT_THROWS_WITH(LoadDisparityImage(colour_path, 8.0), std::invalid_argument, "channels that differ");
}

TEST(MiddleburyPairTest, MissingFilesAndBadScalesAreNamed) {
  CAIRN_EXPECT_THROWS_WITH(MiddleburyPair::Load(kData + "/nowhere", 8.0), std::runtime_error, "nowhere/im2.png",
                           "check the path");
  CAIRN_EXPECT_THROWS_WITH(LoadDisparityImage(kData + "/venus/disp2.png", 0.0), std::invalid_argument, "scale 0");
  CAIRN_EXPECT_THROWS_WITH(LoadDisparityImage(kData + "/venus/disp2.png", std::numeric_limits<double>::infinity()),
                           std::invalid_argument, "scale inf", "finite");
  const cv::Mat a(3, 4, CV_32F, cv::Scalar(1.0f));
  CAIRN_EXPECT_THROWS_WITH(OcclusionFromGroundTruth(a, cv::Mat(3, 5, CV_32F)), std::invalid_argument, "4x3", "5x3");
  CAIRN_EXPECT_THROWS_WITH(OcclusionFromGroundTruth(a, a, -1.0), std::invalid_argument, "tolerance -1");
  // An infinite disparity points outside the image: occluded, not an out-of-range conversion.
  cv::Mat far = a.clone();
  far.at<float>(1, 1) = std::numeric_limits<float>::infinity();
  EXPECT_EQ(OcclusionFromGroundTruth(far, a).at<uint8_t>(1, 1), 255);
}

}  // namespace
}  // namespace cairn::perception
