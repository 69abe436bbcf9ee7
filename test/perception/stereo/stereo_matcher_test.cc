#include "cairn/perception/stereo/stereo_matcher.h"

#include <cmath>
#include <stdexcept>

#include <gtest/gtest.h>

#include "cairn/perception/synthetic/synthetic_stereo_renderer.h"
#include "expect_throws.h"

namespace cairn::perception {
namespace {

StereoMatcher::Options SmallOptions() {
  StereoMatcher::Options options;
  options.cost_volume.cost = CostFunction::kBtSad;
  options.cost_volume.window = 5;
  options.cost_volume.min_disparity = 1;
  options.cost_volume.max_disparity = 16;
  return options;
}

// A fronto-parallel textured wall at 1 m seen with fb = 5 px m: true disparity 5 everywhere.
SyntheticStereoFrame WallPair() {
  SyntheticStereoScene scene;
  ProceduralTexture texture;
  texture.kind = ProceduralTexture::Kind::kNoise;
  texture.scale = 0.02;
  texture.contrast = 60.0;
  scene.AddPlane(Eigen::Vector3d(0.0, 0.0, 1.0), Eigen::Vector3d(0.0, 0.0, -1.0), texture, 1);
  SyntheticStereoRenderer renderer(StereoCalibration{50.0, 50.0, 31.5, 23.5, 0.1}, 64, 48);
  return renderer.Render(scene, Eigen::Isometry3d::Identity());
}

TEST(StereoMatcherTest, MatchesAPairFromFixedInputs) {
  const auto frame = WallPair();
  StereoMatcher matcher(SmallOptions());
  auto context = matcher.CreateDefaultContext();
  matcher.get_left_input_port().FixValue(context.get(), frame.left);
  matcher.get_right_input_port().FixValue(context.get(), frame.right);
  const auto& costs = matcher.get_cost_volume_output_port().Eval<DisparityVolume>(*context);
  EXPECT_EQ(costs.num_disparities(), 16);
  const auto& wta = matcher.get_wta_output_port().Eval<WtaResult>(*context);
  EXPECT_NEAR(wta.disparity.at<float>(24, 40), 5.0, 0.3);
  const auto& confidence = matcher.get_confidence_output_port().Eval<DisparityVolume>(*context);
  double sum = 0.0;
  for (int k = 0; k < confidence.num_disparities(); ++k) sum += confidence.at(24, 40, k);
  EXPECT_NEAR(sum, 1.0, 1e-4);
  EXPECT_GT(confidence.at(24, 40, 4), 0.5);  // disparity 5 = min_disparity + 4
  const auto& model = matcher.get_model_output_port().Eval<ConfidenceModel>(*context);
  EXPECT_EQ(model.type(), ConfidenceModelType::kMerrell);
  EXPECT_GT(model.parameter(), 0.0);  // fitted by maximum likelihood
}

TEST(StereoMatcherTest, UsesAFixedParameterWhenGiven) {
  const auto frame = WallPair();
  auto options = SmallOptions();
  options.model = ConfidenceModelType::kExponential;
  options.parameter = 123.0;
  StereoMatcher matcher(options);
  auto context = matcher.CreateDefaultContext();
  matcher.get_left_input_port().FixValue(context.get(), frame.left);
  matcher.get_right_input_port().FixValue(context.get(), frame.right);
  EXPECT_DOUBLE_EQ(matcher.get_model_output_port().Eval<ConfidenceModel>(*context).parameter(), 123.0);
}

TEST(StereoMatcherTest, RejectsBadOptionsAndEmptyImages) {
  auto options = SmallOptions();
  options.parameter = -1.0;
  EXPECT_THROW(StereoMatcher{options}, std::invalid_argument);
  options = SmallOptions();
  options.cost_volume.window = 4;
  EXPECT_THROW(StereoMatcher{options}, std::invalid_argument);
  StereoMatcher matcher(SmallOptions());
  auto context = matcher.CreateDefaultContext();
  matcher.get_left_input_port().FixValue(context.get(), cv::Mat());
  matcher.get_right_input_port().FixValue(context.get(), WallPair().right);
  CAIRN_EXPECT_THROWS_WITH(matcher.get_wta_output_port().Eval<WtaResult>(*context), std::invalid_argument,
                           "left image is empty");
}

}  // namespace
}  // namespace cairn::perception
