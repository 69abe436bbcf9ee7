#include "cairn/perception/friction/material_features.h"

#include <stdexcept>

#include <gtest/gtest.h>

#include "expect_throws.h"

namespace cairn::perception {
namespace {

TEST(MaterialFeaturesTest, GridCoversTheImage) {
  const MaterialFeatures features(15, 8);
  EXPECT_EQ(features.GridSize(cv::Size(640, 480)), cv::Size(80, 60));
  EXPECT_EQ(features.GridSize(cv::Size(17, 9)), cv::Size(3, 2));
  EXPECT_EQ(features.CentreOf(0, 17), 4);
  EXPECT_EQ(features.CentreOf(2, 17), 16);  // Clamped to the last pixel.
  const cv::Mat image(15, 17, CV_8UC3, cv::Scalar(10, 20, 30));  // at least one window high
  const cv::Mat descriptors = features.Compute(image);
  EXPECT_EQ(descriptors.rows, 6);
  EXPECT_EQ(descriptors.cols, MaterialFeatures::kDimension);
  EXPECT_EQ(descriptors.type(), CV_32F);
}

TEST(MaterialFeaturesTest, FlatImageHasColourButNoTexture) {
  const MaterialFeatures features(9, 4);
  const cv::Mat flat(32, 32, CV_8UC3, cv::Scalar(40, 160, 60));  // BGR green.
  const cv::Mat d = features.Compute(flat);
  for (int i = 0; i < d.rows; ++i) {
    EXPECT_GT(d.at<float>(i, 0), 30.0f);   // L*
    EXPECT_LT(d.at<float>(i, 1), -20.0f);  // a*: green
    for (int k = 3; k < 11; ++k) EXPECT_NEAR(d.at<float>(i, k), 0.0f, 1e-3f) << k;
    EXPECT_NEAR(d.at<float>(i, 11), 1.0f, 1e-5f);  // Every LBP code is "0 brighter neighbours".
  }
}

TEST(MaterialFeaturesTest, StripesAreCoherentAndNoiseIsNot) {
  const MaterialFeatures features(15, 8);
  cv::Mat stripes(64, 64, CV_8UC1);
  for (int y = 0; y < 64; ++y) {
    for (int x = 0; x < 64; ++x) stripes.at<std::uint8_t>(y, x) = (x / 3) % 2 ? 200 : 50;
  }
  cv::Mat noise(64, 64, CV_8UC1);
  cv::RNG rng(3);
  rng.fill(noise, cv::RNG::UNIFORM, 50, 200);
  const cv::Mat s = features.Compute(stripes);
  const cv::Mat n = features.Compute(noise);
  const int centre = 3 * 8 + 3;
  EXPECT_GT(s.at<float>(centre, 8), 0.9f);
  EXPECT_LT(n.at<float>(centre, 8), 0.5f);
  EXPECT_GT(n.at<float>(centre, 9), s.at<float>(centre, 9) * 0.5f);  // Noise has fine-band energy.
  EXPECT_GT(n.at<float>(centre, 6), 1.0f);
}

TEST(MaterialFeaturesTest, BadArgumentsAreNamed) {
  CAIRN_EXPECT_THROWS_WITH(MaterialFeatures(4, 8), std::invalid_argument, "odd and in [3, 1023]", "got 4");
  CAIRN_EXPECT_THROWS_WITH(MaterialFeatures(1025, 8), std::invalid_argument, "odd and in [3, 1023]", "got 1025");
  CAIRN_EXPECT_THROWS_WITH(MaterialFeatures(15, 0), std::invalid_argument, "stride must be in [1, 1023]", "got 0");
  CAIRN_EXPECT_THROWS_WITH(MaterialFeatures(15, 5000), std::invalid_argument, "stride must be in [1, 1023]");
  const MaterialFeatures features;
  CAIRN_EXPECT_THROWS_WITH(features.Compute(cv::Mat(8, 8, CV_32FC3)), std::invalid_argument, "8-bit", "depth 5");
  CAIRN_EXPECT_THROWS_WITH(features.Compute(cv::Mat()), std::invalid_argument, "non-empty");
  // An image smaller than the window would be described by its mirrored border: refused.
  CAIRN_EXPECT_THROWS_WITH(features.Compute(cv::Mat(40, 14, CV_8UC3)), std::invalid_argument, "14x40 pixels",
                           "smaller than the segmenter's 15x15 patch window");
}

}  // namespace
}  // namespace cairn::perception
