#include "cairn/perception/synthetic/synthetic_stereo_source.h"

#include <cmath>
#include <stdexcept>

#include <gtest/gtest.h>

#include "expect_throws.h"

namespace cairn::perception {
namespace {

SyntheticStereoScene WallScene() {
  SyntheticStereoScene scene;
  ProceduralTexture texture;
  texture.kind = ProceduralTexture::Kind::kNoise;
  texture.scale = 0.05;
  scene.AddPlane(Eigen::Vector3d(0.0, 0.0, 2.0), Eigen::Vector3d(0.0, 0.0, -1.0), texture, 3);
  return scene;
}

std::vector<Eigen::Isometry3d> SlideAlongX(int frames) {
  std::vector<Eigen::Isometry3d> poses;
  for (int k = 0; k < frames; ++k) {
    Eigen::Isometry3d X_WC = Eigen::Isometry3d::Identity();
    X_WC.translation().x() = 0.1 * k;
    poses.push_back(X_WC);
  }
  return poses;
}

TEST(SyntheticStereoSourceTest, OutputsTheFrameOfTheCurrentTime) {
  const StereoCalibration calibration{50.0, 50.0, 31.5, 23.5, 0.1};
  SyntheticStereoRenderer renderer(calibration, 64, 48, 0.0, 1);
  SyntheticStereoSource source(WallScene(), renderer, SlideAlongX(3), 0.1);
  EXPECT_EQ(source.FrameIndexAt(0.0), 0);
  EXPECT_EQ(source.FrameIndexAt(0.3 - 0.1 - 0.1), 1);  // 0.1 up to rounding
  EXPECT_EQ(source.FrameIndexAt(0.25), 2);
  EXPECT_EQ(source.FrameIndexAt(7.0), 2);  // holds the last frame
  auto context = source.CreateDefaultContext();
  context->SetTime(0.1);
  const auto expected = renderer.Render(WallScene(), SlideAlongX(3)[1], 1);
  const cv::Mat& left = source.get_left_output_port().Eval<cv::Mat>(*context);
  ASSERT_EQ(left.rows, 48);
  ASSERT_EQ(left.cols, 64);
  EXPECT_EQ(cv::norm(left, expected.left, cv::NORM_INF), 0.0);
  EXPECT_EQ(cv::norm(source.get_right_output_port().Eval<cv::Mat>(*context), expected.right, cv::NORM_INF), 0.0);
  EXPECT_NEAR(source.get_depth_output_port().Eval<cv::Mat>(*context).at<float>(24, 32), 2.0, 1e-3);
  EXPECT_FALSE(source.get_labels_output_port().Eval<cv::Mat>(*context).empty());
  EXPECT_DOUBLE_EQ(source.get_pose_output_port().Eval<Eigen::Isometry3d>(*context).translation().x(), 0.1);
}

TEST(SyntheticStereoSourceTest, RejectsBadArguments) {
  const StereoCalibration calibration{50.0, 50.0, 31.5, 23.5, 0.1};
  SyntheticStereoRenderer renderer(calibration, 64, 48);
  CAIRN_EXPECT_THROWS_WITH(SyntheticStereoSource(WallScene(), renderer, {}, 0.1), std::invalid_argument,
                           "trajectory is empty");
  CAIRN_EXPECT_THROWS_WITH(SyntheticStereoSource(WallScene(), renderer, SlideAlongX(1), 0.0), std::invalid_argument,
                           "period 0.0", "positive");
}

}  // namespace
}  // namespace cairn::perception
