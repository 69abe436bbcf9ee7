#include "cairn/perception/terrain/semantic_fusion.h"

#include <algorithm>
#include <cmath>
#include <string>

#include <gtest/gtest.h>
#include <opencv2/core.hpp>

#include "cairn/perception/friction/builtin_material_segmenter.h"
#include "cairn/perception/synthetic/material_texture.h"
#include "expect_throws.h"
#include "test_paths.h"

namespace cairn::perception {
namespace {

TEST(SemanticFusionTest, AveragesPointsPerCellAndFusesUpdates) {
  GridMap map(Eigen::Vector2i(4, 4), 1.0, Eigen::Vector2d::Zero());
  SemanticFusion::Options options;
  options.measurement_variance = 0.1;
  SemanticFusion fusion(options);
  fusion.AddLayers(&map);
  Eigen::Matrix3Xd points(3, 3);
  points << 0.5, 0.6, -1.5,  //
      0.5, 0.7, -1.5,        //
      0.0, 0.0, 0.0;
  Eigen::MatrixXd p(2, 3);
  p << 0.9, 0.7, 0.0,  //
      0.1, 0.3, 1.0;
  fusion.Integrate(points, p, &map);
  EXPECT_DOUBLE_EQ(map.ValueAt("semantic_plants", Eigen::Vector2d(0.5, 0.5)), 0.8);
  EXPECT_DOUBLE_EQ(map.ValueAt("semantic_water", Eigen::Vector2d(-1.5, -1.5)), 1.0);
  EXPECT_DOUBLE_EQ(map.ValueAt("semantic_plants_variance", Eigen::Vector2d(0.5, 0.5)), 0.1);
  EXPECT_TRUE(std::isnan(map.ValueAt("semantic_plants", Eigen::Vector2d(1.5, 1.5))));
  p.row(0).setZero();
  fusion.Integrate(points, p, &map);  // a second, contradicting update halves the estimate
  EXPECT_DOUBLE_EQ(map.ValueAt("semantic_plants", Eigen::Vector2d(0.5, 0.5)), 0.4);
  EXPECT_DOUBLE_EQ(map.ValueAt("semantic_plants_variance", Eigen::Vector2d(0.5, 0.5)), 0.05);
}

TEST(SemanticFusionTest, RejectsBadInput) {
  GridMap map(Eigen::Vector2i(4, 4), 1.0, Eigen::Vector2d::Zero());
  SemanticFusion fusion;
  fusion.AddLayers(&map);
  Eigen::Matrix3Xd points = Eigen::Matrix3Xd::Zero(3, 2);
  CAIRN_EXPECT_THROWS_WITH(fusion.Integrate(points, Eigen::MatrixXd::Zero(3, 2), &map), std::invalid_argument,
                           "probabilities are 3 x 2; expected 2 classes x 2 points");
  Eigen::MatrixXd p = Eigen::MatrixXd::Zero(2, 2);
  p(1, 1) = 1.5;
  CAIRN_EXPECT_THROWS_WITH(fusion.Integrate(points, p, &map), std::invalid_argument,
                           "probability 1.5 of class 'water' at point 1");
  SemanticFusion::Options twice;
  twice.classes = {"plants", "plants"};
  CAIRN_EXPECT_THROWS_WITH(SemanticFusion{twice}, std::invalid_argument, "'plants' is listed twice");
}

// Seed 001 segments plants and water; our built-in segmenter's labels include grass and water, which the options
// map to those classes without the caller rearranging the segmenter's output.
TEST(SemanticFusionTest, MapsTheBuiltinSegmentersGrassAndWaterToPlantsAndWater) {
  const BuiltinMaterialSegmenter segmenter =
      BuiltinMaterialSegmenter::Load(std::string(CAIRN_SOURCE_DIR) + "/data/models/builtin_material_segmenter.yaml");
  // The ground seen from above at 5 mm per pixel: grass on the left half (x < 0), water on the right.
  constexpr int kRows = 96, kCols = 192;
  constexpr double kPixel = 0.005;
  const MaterialTexture grass = MaterialTexture::Make("grass", 3);
  const MaterialTexture water = MaterialTexture::Make("water", 4);
  cv::Mat image(kRows, kCols, CV_8UC3);
  for (int r = 0; r < kRows; ++r) {
    for (int c = 0; c < kCols; ++c) {
      const Eigen::Vector3d bgr = (c < kCols / 2 ? grass : water).Evaluate(c * kPixel, r * kPixel);
      for (int ch = 0; ch < 3; ++ch) image.at<cv::Vec3b>(r, c)[ch] = cv::saturate_cast<uchar>(bgr[ch]);
    }
  }
  const cv::Mat labels = segmenter.Segment(image);
  const int num_labels = segmenter.num_labels();
  Eigen::Matrix3Xd points(3, kRows * kCols);
  Eigen::MatrixXd probabilities(num_labels, kRows * kCols);
  for (int r = 0; r < kRows; ++r) {
    const float* row = labels.ptr<float>(r);
    for (int c = 0; c < kCols; ++c) {
      const int p = r * kCols + c;
      points.col(p) = Eigen::Vector3d((c + 0.5 - kCols / 2) * kPixel, (r + 0.5 - kRows / 2) * kPixel, 0.0);
      for (int l = 0; l < num_labels; ++l) probabilities(l, p) = row[c * num_labels + l];
    }
  }
  SemanticFusion::Options options;
  options.input_labels = segmenter.labels();
  options.class_labels = {{"plants", {"grass"}}, {"water", {"water"}}};
  SemanticFusion fusion(options);
  EXPECT_EQ(fusion.num_input_rows(), num_labels);
  GridMap map(Eigen::Vector2i(2, 1), kCols * kPixel / 2, Eigen::Vector2d::Zero());
  fusion.AddLayers(&map);
  fusion.Integrate(points, probabilities, &map);
  const Eigen::Vector2d left(-kCols * kPixel / 4, 0.0), right(kCols * kPixel / 4, 0.0);
  EXPECT_GT(map.ValueAt("semantic_plants", left), 0.5);
  EXPECT_LT(map.ValueAt("semantic_water", left), 0.2);
  EXPECT_GT(map.ValueAt("semantic_water", right), 0.5);
  EXPECT_LT(map.ValueAt("semantic_plants", right), 0.2);

  // A class is the sum of its labels, averaged over the cell's points (the first update of a cell is its average).
  const auto row_of = [&](const std::string& label) {
    return static_cast<int>(std::find(segmenter.labels().begin(), segmenter.labels().end(), label) -
                            segmenter.labels().begin());
  };
  double water_and_sand = 0.0;
  for (int p = 0; p < kRows * kCols; ++p) {
    if (points(0, p) > 0.0) water_and_sand += probabilities(row_of("water"), p) + probabilities(row_of("sand"), p);
  }
  water_and_sand /= kRows * kCols / 2;
  SemanticFusion::Options wider = options;
  wider.class_labels["water"] = {"water", "sand"};
  SemanticFusion wide(wider);
  GridMap map2(Eigen::Vector2i(2, 1), kCols * kPixel / 2, Eigen::Vector2d::Zero());
  wide.AddLayers(&map2);
  wide.Integrate(points, probabilities, &map2);
  EXPECT_NEAR(map2.ValueAt("semantic_water", right), water_and_sand, 1e-9);
  EXPECT_DOUBLE_EQ(map2.ValueAt("semantic_plants", left), map.ValueAt("semantic_plants", left));
}

TEST(SemanticFusionTest, RejectsBadLabelMaps) {
  SemanticFusion::Options o;
  o.input_labels = {"asphalt", "grass", "water"};
  o.class_labels = {{"plants", {"grass"}}};
  CAIRN_EXPECT_THROWS_WITH(SemanticFusion{o}, std::invalid_argument, "class 'water' has no input label",
                           "class_labels");
  o.class_labels = {{"plants", {"grass"}}, {"water", {"lake"}}};
  CAIRN_EXPECT_THROWS_WITH(SemanticFusion{o}, std::invalid_argument, "label 'lake'", "not an input label");
  o.class_labels = {{"plants", {"grass"}}, {"water", {"water", "grass"}}};
  CAIRN_EXPECT_THROWS_WITH(SemanticFusion{o}, std::invalid_argument, "label 'grass' belongs to classes");
  o.class_labels = {{"plants", {"grass"}}, {"water", {"water"}}, {"rocks", {"asphalt"}}};
  CAIRN_EXPECT_THROWS_WITH(SemanticFusion{o}, std::invalid_argument, "class 'rocks'", "not one of the classes");
  o.input_labels = {"grass", "water", "grass"};
  o.class_labels = {{"plants", {"grass"}}, {"water", {"water"}}};
  CAIRN_EXPECT_THROWS_WITH(SemanticFusion{o}, std::invalid_argument, "input label 'grass' is listed twice");
  SemanticFusion::Options unlabelled;
  unlabelled.class_labels = {{"plants", {"grass"}}};
  CAIRN_EXPECT_THROWS_WITH(SemanticFusion{unlabelled}, std::invalid_argument,
                           "class_labels is given without input_labels");

  o.input_labels = {"asphalt", "grass", "moss", "water"};
  o.class_labels = {{"plants", {"grass", "moss"}}, {"water", {"water"}}};
  SemanticFusion fusion(o);
  GridMap map(Eigen::Vector2i(4, 4), 1.0, Eigen::Vector2d::Zero());
  fusion.AddLayers(&map);
  const Eigen::Matrix3Xd points = Eigen::Matrix3Xd::Zero(3, 1);
  Eigen::MatrixXd p(4, 1);
  p << 0.0, 0.7, 0.6, 0.0;
  CAIRN_EXPECT_THROWS_WITH(fusion.Integrate(points, p, &map), std::invalid_argument,
                           "the labels of class 'plants' sum to 1.3 (1 + 0.3) at point 0");
  p << 0.0, 0.5, 0.5 + 4e-6, 0.0;  // float rounding above 1: accepted, the class's probability is 1
  fusion.Integrate(points, p, &map);
  EXPECT_DOUBLE_EQ(map.ValueAt("semantic_plants", Eigen::Vector2d(0.5, 0.5)), 1.0);
  CAIRN_EXPECT_THROWS_WITH(fusion.Integrate(points, Eigen::MatrixXd::Zero(2, 1), &map), std::invalid_argument,
                           "expected 4 input labels x 1 points");
  p << 0.0, 0.3, -0.1, 0.0;
  CAIRN_EXPECT_THROWS_WITH(fusion.Integrate(points, p, &map), std::invalid_argument,
                           "probability -0.1 of label 'moss' at point 0");
}

}  // namespace
}  // namespace cairn::perception
