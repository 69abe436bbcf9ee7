#include "cairn/perception/stereo/disparity_to_depth.h"

#include <cmath>
#include <stdexcept>

#include <gtest/gtest.h>

#include "cairn/perception/stereo/stereo_matcher.h"
#include "cairn/perception/synthetic/synthetic_stereo_renderer.h"
#include "expect_throws.h"

namespace cairn::perception {
namespace {

const StereoCalibration kCalibration{50.0, 50.0, 31.5, 23.5, 0.1};  // fx * baseline = 5 px m

WtaResult TwoByTwo() {
  WtaResult wta;
  wta.disparity = (cv::Mat_<float>(2, 2) << 5.0f, 2.5f, 0.0f, std::nanf(""));
  wta.lr_consistent = (cv::Mat_<std::uint8_t>(2, 2) << 255, 0, 255, 255);
  wta.peak_ratio = (cv::Mat_<float>(2, 2) << 3.0f, 1.1f, 2.0f, 2.0f);
  return wta;
}

TEST(DisparityToDepthTest, DepthIsFocalTimesBaselineOverDisparityWhereTheWinnerIsTrusted) {
  DisparityToDepth checked(kCalibration);
  cv::Mat depth;
  checked.Convert(TwoByTwo(), &depth);
  ASSERT_EQ(depth.type(), CV_32F);
  EXPECT_FLOAT_EQ(depth.at<float>(0, 0), 1.0f);
  EXPECT_TRUE(std::isnan(depth.at<float>(0, 1)));  // failed the left-right check
  EXPECT_TRUE(std::isnan(depth.at<float>(1, 0)));  // zero disparity: at infinity, no point
  EXPECT_TRUE(std::isnan(depth.at<float>(1, 1)));  // no winner

  DisparityToDepth unchecked(kCalibration, {false, 1.0});
  unchecked.Convert(TwoByTwo(), &depth);
  EXPECT_FLOAT_EQ(depth.at<float>(0, 1), 2.0f);

  DisparityToDepth peaked(kCalibration, {false, 1.5});
  peaked.Convert(TwoByTwo(), &depth);
  EXPECT_FLOAT_EQ(depth.at<float>(0, 0), 1.0f);
  EXPECT_TRUE(std::isnan(depth.at<float>(0, 1)));  // peak ratio 1.1: ambiguous
}

TEST(DisparityToDepthTest, RecoversARenderedWallsDepthThroughTheMatcher) {
  SyntheticStereoScene scene;
  ProceduralTexture texture;
  texture.kind = ProceduralTexture::Kind::kNoise;
  texture.scale = 0.02;
  texture.contrast = 60.0;
  scene.AddPlane(Eigen::Vector3d(0.0, 0.0, 1.0), Eigen::Vector3d(0.0, 0.0, -1.0), texture, 1);
  const SyntheticStereoFrame frame =
      SyntheticStereoRenderer(kCalibration, 64, 48).Render(scene, Eigen::Isometry3d::Identity());
  StereoMatcher::Options options;
  options.cost_volume.window = 5;
  options.cost_volume.min_disparity = 1;
  options.cost_volume.max_disparity = 16;
  StereoMatcher matcher(options);
  DisparityToDepth to_depth(kCalibration);
  auto matcher_context = matcher.CreateDefaultContext();
  matcher.get_left_input_port().FixValue(matcher_context.get(), frame.left);
  matcher.get_right_input_port().FixValue(matcher_context.get(), frame.right);
  auto context = to_depth.CreateDefaultContext();
  to_depth.get_wta_input_port().FixValue(context.get(),
                                         matcher.get_wta_output_port().Eval<WtaResult>(*matcher_context));
  const auto& depth = to_depth.get_depth_output_port().Eval<cv::Mat>(*context);
  ASSERT_EQ(depth.size(), frame.left.size());
  int valid = 0;
  for (int y = 8; y < 40; ++y) {
    for (int x = 24; x < 56; ++x) {
      if (std::isnan(depth.at<float>(y, x))) continue;
      ++valid;
      EXPECT_NEAR(depth.at<float>(y, x), 1.0, 0.06) << "at (" << x << ", " << y << ")";
    }
  }
  EXPECT_GT(valid, 32 * 32 * 9 / 10);
}

TEST(DisparityToDepthTest, RejectsBadOptionsAndInputs) {
  CAIRN_EXPECT_THROWS_WITH(DisparityToDepth(kCalibration, {true, 0.5}), std::invalid_argument,
                           "min_peak_ratio must be a finite number >= 1 (1 keeps every pixel); got 0.5");
  StereoCalibration bad = kCalibration;
  bad.baseline = 0.0;
  EXPECT_THROW(DisparityToDepth{bad}, std::invalid_argument);
  DisparityToDepth to_depth(kCalibration);
  WtaResult wta = TwoByTwo();
  wta.lr_consistent = cv::Mat();
  cv::Mat depth;
  CAIRN_EXPECT_THROWS_WITH(to_depth.Convert(wta, &depth), std::invalid_argument,
                           "lr_consistent must be a CV_8U image of the disparity's size");
  wta.disparity.convertTo(wta.disparity, CV_64F);
  CAIRN_EXPECT_THROWS_WITH(to_depth.Convert(wta, &depth), std::invalid_argument, "must be CV_32F");
}

}  // namespace
}  // namespace cairn::perception
