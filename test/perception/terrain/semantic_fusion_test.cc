#include "cairn/perception/terrain/semantic_fusion.h"

#include <cmath>

#include <gtest/gtest.h>

#include "expect_throws.h"

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

}  // namespace
}  // namespace cairn::perception
