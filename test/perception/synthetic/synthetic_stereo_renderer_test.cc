#include "cairn/perception/synthetic/synthetic_stereo_renderer.h"

#include <cmath>
#include <stdexcept>

#include <gtest/gtest.h>

#include "cairn/perception/synthetic/synthetic_stereo_source.h"
#include "expect_throws.h"

namespace cairn::perception {
namespace {

// A wall 2 m ahead (label 3) and a box in front of it (label 5).
SyntheticStereoScene WallAndBox(int* wall, int* box) {
  SyntheticStereoScene scene;
  ProceduralTexture texture;
  texture.scale = 0.05;
  *wall = scene.AddPlane(Eigen::Vector3d(0.0, 0.0, 2.0), Eigen::Vector3d(0.0, 0.0, -1.0), texture, 3);
  Eigen::Isometry3d X_WB = Eigen::Isometry3d::Identity();
  X_WB.translation() << 0.2, 0.0, 1.5;
  *box = scene.AddBox(X_WB, Eigen::Vector3d(0.1, 0.15, 0.1), texture, 5);
  return scene;
}

const StereoCalibration kCalibration{60.0, 60.0, 31.5, 23.5, 0.1};

TEST(SyntheticStereoRendererTest, GreyScenesHaveNoColourImages) {
  int wall = 0, box = 0;
  const SyntheticStereoScene scene = WallAndBox(&wall, &box);
  EXPECT_FALSE(scene.has_colour_textures());
  const auto frame = SyntheticStereoRenderer(kCalibration, 64, 48, 4.0, 2).Render(scene, Eigen::Isometry3d::Identity());
  EXPECT_TRUE(frame.left_colour.empty());
  EXPECT_TRUE(frame.right_colour.empty());
  EXPECT_EQ(frame.left.type(), CV_8UC1);
}

TEST(SyntheticStereoRendererTest, ColourTexturesGiveColourImagesWhoseLumaIsTheGreyImage) {
  int wall = 0, box = 0;
  SyntheticStereoScene scene = WallAndBox(&wall, &box);
  // Red-and-blue stripes along the wall's first texture axis; a plain green box, its faces told apart by which
  // texture coordinate pair they pass (each face sees two of the box's three axes).
  scene.SetColourTexture(wall, [](double u, double) {
    return std::fmod(std::abs(u), 0.2) < 0.1 ? Eigen::Vector3d(0.0, 0.0, 200.0) : Eigen::Vector3d(200.0, 0.0, 0.0);
  });
  scene.SetColourTexture(box, [](double, double) { return Eigen::Vector3d(10.0, 180.0, 20.0); });
  EXPECT_TRUE(scene.has_colour_textures());
  const SyntheticStereoRenderer renderer(kCalibration, 64, 48, 0.0, 1);
  const auto frame = renderer.Render(scene, Eigen::Isometry3d::Identity());
  ASSERT_EQ(frame.left_colour.type(), CV_8UC3);
  ASSERT_EQ(frame.right_colour.size(), frame.right.size());
  int box_pixels = 0;
  for (int y = 0; y < 48; ++y) {
    for (int x = 0; x < 64; ++x) {
      const cv::Vec3b c = frame.left_colour.at<cv::Vec3b>(y, x);
      const double luma = 0.114 * c[0] + 0.587 * c[1] + 0.299 * c[2];
      EXPECT_NEAR(frame.left.at<uint8_t>(y, x), luma, 1.0) << y << ", " << x;
      const cv::Mat& l = frame.labels;
      const bool interior = x > 0 && y > 0 && x < 63 && y < 47 && l.at<int>(y - 1, x) == l.at<int>(y + 1, x) &&
                            l.at<int>(y, x - 1) == l.at<int>(y, x + 1);
      if (frame.labels.at<int>(y, x) == 5 && interior) {
        ++box_pixels;
        EXPECT_EQ(c, cv::Vec3b(10, 180, 20));
      }
      if (frame.labels.at<int>(y, x) == 3 && interior) {
        EXPECT_EQ(c[1], 0);  // The wall is red or blue (or a blend of them).
      }
    }
  }
  EXPECT_GT(box_pixels, 20);
  // The source passes the colour pair through.
  SyntheticStereoSource source(scene, renderer, {Eigen::Isometry3d::Identity()}, 0.1);
  auto context = source.CreateDefaultContext();
  EXPECT_EQ(cv::norm(source.get_left_colour_output_port().Eval<cv::Mat>(*context), frame.left_colour,
                     cv::NORM_INF),
            0.0);
  EXPECT_EQ(cv::norm(source.get_right_colour_output_port().Eval<cv::Mat>(*context), frame.right_colour, cv::NORM_INF),
            0.0);
}

TEST(SyntheticStereoRendererTest, ColourNoiseLeavesTheGreyNoiseAlone) {
  // Grey images of a coloured scene are the colour's luma plus the same noise draws as any grey scene: adding a
  // colour texture that equals the grey texture's intensity leaves the grey images unchanged.
  int wall = 0, box = 0;
  const SyntheticStereoScene grey = WallAndBox(&wall, &box);
  SyntheticStereoScene coloured = WallAndBox(&wall, &box);
  coloured.SetColourTexture(box, [](double u, double v) {
    ProceduralTexture texture;
    texture.scale = 0.05;
    return Eigen::Vector3d::Constant(texture.Evaluate(u, v));
  });
  const SyntheticStereoRenderer renderer(kCalibration, 64, 48, 9.0, 4);
  const auto a = renderer.Render(grey, Eigen::Isometry3d::Identity(), 3);
  const auto b = renderer.Render(coloured, Eigen::Isometry3d::Identity(), 3);
  EXPECT_LE(cv::norm(a.left, b.left, cv::NORM_INF), 1.0);  // Luma weights sum to 1 up to rounding.
  EXPECT_LE(cv::norm(a.right, b.right, cv::NORM_INF), 1.0);
}

TEST(SyntheticStereoRendererTest, SetColourTextureRejectsBadArguments) {
  int wall = 0, box = 0;
  SyntheticStereoScene scene = WallAndBox(&wall, &box);
  CAIRN_EXPECT_THROWS_WITH(scene.SetColourTexture(2, [](double, double) { return Eigen::Vector3d::Zero(); }),
                           std::invalid_argument, "object 2 does not exist", "2 objects");
  CAIRN_EXPECT_THROWS_WITH(scene.SetColourTexture(0, nullptr), std::invalid_argument, "empty function");
}

TEST(SyntheticStereoRendererTest, RefusesSizesAndIndicesThatWouldOverflow) {
  const StereoCalibration calibration{100.0, 100.0, 15.5, 11.5, 0.1};
  CAIRN_EXPECT_THROWS_WITH(SyntheticStereoRenderer(calibration, 100000, 100000), std::invalid_argument,
                           "100000x100000", "at most 67108864 pixels");
  CAIRN_EXPECT_THROWS_WITH(SyntheticStereoRenderer(calibration, 32, 24, std::nan("")), std::invalid_argument,
                           "noise variance nan");
  int wall = 0, box = 0;
  const SyntheticStereoScene scene = WallAndBox(&wall, &box);
  const SyntheticStereoRenderer renderer(calibration, 32, 24);
  CAIRN_EXPECT_THROWS_WITH(renderer.Render(scene, Eigen::Isometry3d::Identity(), -1), std::invalid_argument,
                           "frame index -1 is negative");
}

}  // namespace
}  // namespace cairn::perception
