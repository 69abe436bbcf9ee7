#include "cairn/perception/synthetic/material_scene.h"

#include <set>
#include <stdexcept>

#include <gtest/gtest.h>

#include "expect_throws.h"

namespace cairn::perception {
namespace {

MaterialScene::Options Small() {
  MaterialScene::Options options;
  options.width = 96;
  options.height = 72;
  return options;
}

TEST(MaterialSceneTest, RendersAreDeterministicBySeedAndDifferAcrossSeeds) {
  const MaterialScene scene(Small());
  const MaterialScene::Rendering a = scene.Render(7);
  const MaterialScene::Rendering b = scene.Render(7);
  const MaterialScene::Rendering c = scene.Render(8);
  ASSERT_EQ(a.image.type(), CV_8UC3);
  ASSERT_EQ(a.labels.type(), CV_8UC1);
  EXPECT_EQ(a.image.size(), cv::Size(96, 72));
  EXPECT_EQ(a.labels.size(), cv::Size(96, 72));
  EXPECT_EQ(cv::norm(a.image, b.image, cv::NORM_INF), 0.0);
  EXPECT_EQ(cv::norm(a.labels, b.labels, cv::NORM_INF), 0.0);
  EXPECT_GT(cv::norm(a.image, c.image, cv::NORM_L1), 0.0);
}

TEST(MaterialSceneTest, LabelsCoverTheLabelSpaceAcrossScenes) {
  const MaterialScene scene(Small());
  ASSERT_EQ(scene.options().labels.size(), 14u);
  std::set<int> seen;
  int sky_scenes = 0;
  for (std::uint32_t seed = 0; seed < 30; ++seed) {
    const MaterialScene::Rendering r = scene.Render(seed);
    std::set<int> in_scene;
    for (int y = 0; y < r.labels.rows; ++y) {
      for (int x = 0; x < r.labels.cols; ++x) in_scene.insert(r.labels.at<std::uint8_t>(y, x));
    }
    for (int label : in_scene) {
      ASSERT_LT(label, 14) << "seed " << seed;
      seen.insert(label);
    }
    EXPECT_GE(in_scene.size(), 2u) << "seed " << seed;  // Several regions are visible in every scene.
    if (in_scene.count(9) != 0) ++sky_scenes;           // "sky"
  }
  EXPECT_EQ(seen.size(), 14u);
  EXPECT_GT(sky_scenes, 2);
}

TEST(MaterialSceneTest, SkyIsUnlabelledWhenNotInTheLabelSpace) {
  MaterialScene::Options options = Small();
  options.labels = {"asphalt", "grass", "wood"};
  const MaterialScene scene(options);
  EXPECT_EQ(scene.options().ground_labels.size(), 3u);
  EXPECT_EQ(scene.options().box_labels, std::vector<std::string>{"wood"});
  int unlabelled = 0;
  for (std::uint32_t seed = 0; seed < 20; ++seed) {
    const MaterialScene::Rendering r = scene.Render(seed);
    for (int y = 0; y < r.labels.rows; ++y) {
      for (int x = 0; x < r.labels.cols; ++x) {
        const int label = r.labels.at<std::uint8_t>(y, x);
        ASSERT_TRUE(label < 3 || label == MaterialScene::kNoLabel) << label;
        unlabelled += label == MaterialScene::kNoLabel;
      }
    }
  }
  EXPECT_GT(unlabelled, 0);
}

TEST(MaterialSceneTest, NoiseChangesColoursButNotLabels) {
  MaterialScene::Options noisy_options = Small();
  noisy_options.noise_stddev = 8.0;
  const MaterialScene clean(Small());
  const MaterialScene noisy(noisy_options);
  const MaterialScene::Rendering a = clean.Render(3);
  const MaterialScene::Rendering b = noisy.Render(3);
  EXPECT_EQ(cv::norm(a.labels, b.labels, cv::NORM_INF), 0.0);
  cv::Mat difference;
  cv::absdiff(a.image, b.image, difference);
  const double mean_difference = cv::mean(difference)[0];
  EXPECT_GT(mean_difference, 3.0);   // E|N(0, 8²)| ≈ 6.4, less where clipped.
  EXPECT_LT(mean_difference, 10.0);
}

TEST(MaterialSceneTest, SupersamplingSmoothsButKeepsTheScene) {
  MaterialScene::Options options = Small();
  options.samples_per_axis = 2;
  const MaterialScene::Rendering a = MaterialScene(Small()).Render(4);
  const MaterialScene::Rendering b = MaterialScene(options).Render(4);
  EXPECT_EQ(cv::norm(a.labels, b.labels, cv::NORM_INF), 0.0);
  EXPECT_GT(cv::norm(a.image, b.image, cv::NORM_L1), 0.0);
  cv::Mat difference;
  cv::absdiff(a.image, b.image, difference);
  EXPECT_LT(cv::mean(difference)[0], 40.0);
}

TEST(MaterialSceneTest, BadOptionsAreNamed) {
  MaterialScene::Options options = Small();
  options.width = 0;
  CAIRN_EXPECT_THROWS_WITH(MaterialScene{options}, std::invalid_argument, "image size must be positive", "0x72");
  options = Small();
  options.field_of_view_deg = 180.0;
  CAIRN_EXPECT_THROWS_WITH(MaterialScene{options}, std::invalid_argument, "field_of_view_deg", "180");
  options = Small();
  options.num_regions = 0;
  CAIRN_EXPECT_THROWS_WITH(MaterialScene{options}, std::invalid_argument, "num_regions", "got 0");
  options = Small();
  options.num_boxes = -1;
  CAIRN_EXPECT_THROWS_WITH(MaterialScene{options}, std::invalid_argument, "num_boxes", "-1");
  options = Small();
  options.noise_stddev = -1.0;
  CAIRN_EXPECT_THROWS_WITH(MaterialScene{options}, std::invalid_argument, "noise_stddev", "-1");
  options = Small();
  options.samples_per_axis = 0;
  CAIRN_EXPECT_THROWS_WITH(MaterialScene{options}, std::invalid_argument, "samples_per_axis", "got 0");
  options = Small();
  options.labels = {"asphalt", "gras"};
  CAIRN_EXPECT_THROWS_WITH(MaterialScene{options}, std::invalid_argument, "'gras'", "did you mean 'grass'");
  options = Small();
  options.labels = {"asphalt", "grass"};
  options.box_labels = {"wood"};
  CAIRN_EXPECT_THROWS_WITH(MaterialScene{options}, std::invalid_argument, "box_labels names 'wood'",
                           "add it to labels");
  options = Small();
  options.labels = {"sky"};
  CAIRN_EXPECT_THROWS_WITH(MaterialScene{options}, std::invalid_argument, "only 'sky'", "add ground materials");
}

}  // namespace
}  // namespace cairn::perception
