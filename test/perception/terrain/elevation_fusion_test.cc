#include "cairn/perception/terrain/elevation_fusion.h"

#include <cmath>
#include <cstring>
#include <random>

#include <gtest/gtest.h>

#include "cairn/perception/terrain/kalman_cell_update.h"
#include "expect_throws.h"

namespace cairn::perception {
namespace {

TEST(KalmanCellUpdateTest, ConvergesToTheMeanWithThePredictedVariance) {
  std::mt19937 rng(7);
  std::normal_distribution<double> noise(0.3, 0.05);
  double mean = NAN, variance = NAN, sum = 0.0;
  const int n = 400;
  for (int k = 0; k < n; ++k) {
    const double z = noise(rng);
    sum += z;
    KalmanCellUpdate(z, 0.05 * 0.05, &mean, &variance);
  }
  // Equal variances: the Kalman estimate is exactly the sample mean, with variance s^2 / n.
  EXPECT_NEAR(mean, sum / n, 1e-12);
  EXPECT_NEAR(variance, 0.05 * 0.05 / n, 1e-15);
  EXPECT_NEAR(mean, 0.3, 4.0 * 0.05 / std::sqrt(n));
}

TEST(KalmanCellUpdateTest, WeighsByInverseVariance) {
  double mean = 1.0, variance = 1.0;
  KalmanCellUpdate(3.0, 3.0, &mean, &variance);
  EXPECT_DOUBLE_EQ(mean, (3.0 * 1.0 + 1.0 * 3.0) / 4.0);
  EXPECT_DOUBLE_EQ(variance, 0.75);
}

TEST(RangeVarianceModelTest, QuadraticInRange) {
  RangeVarianceModel m;
  EXPECT_DOUBLE_EQ(m.StdDev(0.77), 0.0024);
  EXPECT_DOUBLE_EQ(m.StdDev(2.77), 0.0024 + 0.0066 * 4.0);
  EXPECT_LT(m.Variance(1.0), m.Variance(3.0));
  m.a = 0.0;
  CAIRN_EXPECT_THROWS_WITH(m.Validate(), std::invalid_argument, "a = 0 m");
}

// Points at two ranges land in the same cell: the fused height weighs them by the model's inverse variances.
TEST(ElevationFusionTest, FusesPointsWithRangeVariance) {
  GridMap map(Eigen::Vector2i(10, 10), 0.1, Eigen::Vector2d::Zero());
  ElevationFusion::AddLayers(&map);
  ElevationFusion::Options options;
  options.num_threads = 2;
  ElevationFusion fusion(options);
  Eigen::Matrix3Xd points(3, 4);
  points << 0.01, 0.02, 5.0, NAN,  //
      0.01, 0.02, 0.0, 0.0,        //
      0.10, 0.20, 0.0, 0.0;
  const Eigen::Vector3d sensor(0.0, 0.0, 1.0);
  const auto& stats = fusion.Integrate(points, sensor, &map);
  EXPECT_EQ(stats.points, 4);
  EXPECT_EQ(stats.fused, 2);
  EXPECT_EQ(stats.outside_map, 1);
  EXPECT_EQ(stats.rejected, 1);
  const double v1 = options.noise.Variance((points.col(0) - sensor).norm());
  const double v2 = options.noise.Variance((points.col(1) - sensor).norm());
  const double expected = (v2 * 0.10 + v1 * 0.20) / (v1 + v2);
  EXPECT_NEAR(map.ValueAt("elevation", Eigen::Vector2d(0.01, 0.01)), expected, 1e-12);
  EXPECT_NEAR(map.ValueAt("elevation_variance", Eigen::Vector2d(0.01, 0.01)), v1 * v2 / (v1 + v2), 1e-15);
  EXPECT_TRUE(std::isnan(map.ValueAt("elevation", Eigen::Vector2d(0.3, 0.3))));
}

// A flat floor at z = 0 seen by a camera 1 m up looking straight down comes out flat, and the thread count does
// not change a bit of the result.
TEST(ElevationFusionTest, DepthImageOfAFloorIsDeterministic) {
  cv::Mat depth(48, 64, CV_32FC1, cv::Scalar(1.0f));
  depth.at<float>(0, 0) = 0.0f;  // no return
  ElevationFusion::Intrinsics K{50.0, 50.0, 32.0, 24.0};
  Eigen::Isometry3d X_WC = Eigen::Isometry3d::Identity();
  X_WC.linear() = Eigen::AngleAxisd(M_PI, Eigen::Vector3d::UnitX()).toRotationMatrix();  // z down
  X_WC.translation() = Eigen::Vector3d(0.0, 0.0, 1.0);
  GridMap a(Eigen::Vector2i(40, 40), 0.05, Eigen::Vector2d::Zero());
  GridMap b = a;
  ElevationFusion::AddLayers(&a);
  ElevationFusion::AddLayers(&b);
  ElevationFusion::Options one;
  one.num_threads = 1;
  ElevationFusion::Options two;
  two.num_threads = 2;
  ElevationFusion f1(one), f2(two);
  EXPECT_EQ(f1.IntegrateDepth(depth, K, X_WC, &a).fused, 64 * 48 - 1);
  f2.IntegrateDepth(depth, K, X_WC, &b);
  for (int layer = 0; layer < 2; ++layer) {  // bitwise, so that NaN (unknown) cells compare equal
    EXPECT_EQ(std::memcmp(a.layer_data(layer).data(), b.layer_data(layer).data(), sizeof(double) * 1600), 0);
  }
  EXPECT_NEAR(a.ValueAt("elevation", Eigen::Vector2d(0.1, -0.1)), 0.0, 1e-12);
  CAIRN_EXPECT_THROWS_WITH(f1.IntegrateDepth(cv::Mat(4, 4, CV_8UC1), K, X_WC, &a), std::invalid_argument,
                           "CV_32FC1");
  CAIRN_EXPECT_THROWS_WITH(f1.IntegrateDepth(depth, ElevationFusion::Intrinsics{0.0, 50.0, 1.0, 1.0}, X_WC, &a),
                           std::invalid_argument, "fx = 0");
  GridMap bare(Eigen::Vector2i(4, 4), 0.05, Eigen::Vector2d::Zero());
  CAIRN_EXPECT_THROWS_WITH(f1.IntegrateDepth(depth, K, X_WC, &bare), std::invalid_argument,
                           "no layer named 'elevation'");
}

}  // namespace
}  // namespace cairn::perception
