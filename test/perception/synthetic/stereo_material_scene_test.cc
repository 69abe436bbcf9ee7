#include "cairn/perception/synthetic/stereo_material_scene.h"

#include <cstdio>
#include <set>
#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>

#include "cairn/perception/evaluation/material_segmentation_score.h"
#include "cairn/perception/friction/builtin_material_segmenter.h"
#include "cairn/perception/synthetic/synthetic_stereo_source.h"
#include "expect_throws.h"

namespace cairn::perception {
namespace {

StereoMaterialScene::Options SmallOptions() {
  StereoMaterialScene::Options options;
  options.width = 128;
  options.height = 96;
  return options;
}

TEST(StereoMaterialSceneTest, RendersAreColourLabelledAndDeterministic) {
  const StereoMaterialScene scene(SmallOptions());
  const auto a = scene.Render(7);
  const auto b = scene.Render(7);
  ASSERT_EQ(a.image.type(), CV_8UC3);
  ASSERT_EQ(a.labels.type(), CV_8UC1);
  EXPECT_EQ(cv::norm(a.image, b.image, cv::NORM_INF), 0.0);
  EXPECT_EQ(cv::norm(a.labels, b.labels, cv::NORM_INF), 0.0);
  // The label image is the stereo frame's ground truth, and the stereo pair and depth come with it.
  EXPECT_EQ(a.image.data, a.frame.left_colour.data);
  EXPECT_FALSE(a.frame.left.empty());
  EXPECT_FALSE(a.frame.depth.empty());
  for (int y = 0; y < a.labels.rows; ++y) {
    for (int x = 0; x < a.labels.cols; ++x) {
      const int truth = a.frame.labels.at<int>(y, x);
      EXPECT_EQ(a.labels.at<uint8_t>(y, x), truth < 0 ? 255 : truth);
    }
  }
  // Over a few scenes, most materials appear.
  std::set<int> seen;
  for (std::uint32_t seed = 1; seed <= 6; ++seed) {
    const cv::Mat labels = scene.Render(seed).labels;
    for (int y = 0; y < labels.rows; ++y) {
      for (int x = 0; x < labels.cols; ++x) seen.insert(labels.at<uint8_t>(y, x));
    }
  }
  EXPECT_GE(seen.size(), 8u);
  EXPECT_NE(cv::norm(scene.Render(1).image, scene.Render(2).image, cv::NORM_INF), 0.0);
}

TEST(StereoMaterialSceneTest, TheStereoSourceRendersTheScenario) {
  const StereoMaterialScene scene(SmallOptions());
  const StereoMaterialScene::Scenario scenario = scene.MakeScenario(3);
  SyntheticStereoSource source(scenario.scene, scene.renderer(), {scenario.X_WC}, 0.1);
  auto context = source.CreateDefaultContext();
  const auto expected = scene.renderer().Render(scenario.scene, scenario.X_WC, 0);
  EXPECT_EQ(cv::norm(source.get_left_colour_output_port().Eval<cv::Mat>(*context), expected.left_colour,
                     cv::NORM_INF),
            0.0);
  EXPECT_EQ(cv::norm(source.get_labels_output_port().Eval<cv::Mat>(*context), expected.labels, cv::NORM_INF), 0.0);
}

TEST(StereoMaterialSceneTest, BuiltinSegmenterTrainedOnStereoRendersIsAccurateOnHeldOutOnes) {
  const StereoMaterialScene scene(SmallOptions());
  std::vector<cv::Mat> images, labels;
  for (std::uint32_t seed = 1; seed <= 24; ++seed) {
    auto r = scene.Render(seed);
    images.push_back(r.image);
    labels.push_back(r.labels);
  }
  BuiltinMaterialSegmenter::TrainingOptions options;
  options.epochs = 30;
  const BuiltinMaterialSegmenter segmenter =
      BuiltinMaterialSegmenter::Train(scene.options().labels, images, labels, options);
  MaterialSegmentationScore score(segmenter.num_labels());
  for (std::uint32_t seed = 50000; seed < 50008; ++seed) {
    const auto r = scene.Render(seed);
    score.Add(segmenter.Segment(r.image), r.labels);
  }
  std::printf("stereo-source renders: held-out pixel accuracy %.3f, class-average accuracy %.3f, ECE %.3f\n",
              score.pixel_accuracy(), score.class_average_accuracy(), score.expected_calibration_error());
  EXPECT_GT(score.pixel_accuracy(), 0.5);
  EXPECT_GT(score.class_average_accuracy(), 0.4);
}

TEST(StereoMaterialSceneTest, RejectsBadOptions) {
  auto options = SmallOptions();
  options.tiles_per_side = 0;
  CAIRN_EXPECT_THROWS_WITH(StereoMaterialScene{options}, std::invalid_argument, "tiles_per_side", "got 0");
  options = SmallOptions();
  options.baseline = -0.1;
  CAIRN_EXPECT_THROWS_WITH(StereoMaterialScene{options}, std::invalid_argument, "baseline must be > 0");
  options = SmallOptions();
  options.box_labels = {"lava"};
  CAIRN_EXPECT_THROWS_WITH(StereoMaterialScene{options}, std::invalid_argument, "box_labels names 'lava'");
  options = SmallOptions();
  options.labels = {"wud"};
  CAIRN_EXPECT_THROWS_WITH(StereoMaterialScene{options}, std::invalid_argument, "no texture for label 'wud'", "wood");
}

}  // namespace
}  // namespace cairn::perception
