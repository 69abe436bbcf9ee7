#include "cairn/perception/haptics/point_cloud_reduction.h"

#include <limits>
#include <random>
#include <stdexcept>

#include "expect_throws.h"

namespace cairn::perception {
namespace {

Eigen::Matrix3Xd RandomCloud(int n, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-0.1, 0.1);
  Eigen::Matrix3Xd points(3, n);
  for (int i = 0; i < n; ++i) points.col(i) = Eigen::Vector3d(u(rng), u(rng), u(rng));
  return points;
}

TEST(PointCloudReductionTest, MinDistanceKeepsGreedyOrderAndSpacing) {
  Eigen::Matrix3Xd points(3, 4);
  points << 0.0, 0.005, 0.012, 0.02,  //
      0.0, 0.0, 0.0, 0.0,             //
      0.0, 0.0, 0.0, 0.0;
  // 0.005 is within 1 cm of 0; 0.012 is not; 0.02 is within 1 cm of 0.012.
  const Eigen::Matrix3Xd kept = DownsampleByMinDistance(points, 0.01);
  ASSERT_EQ(kept.cols(), 2);
  EXPECT_EQ(kept(0, 0), 0.0);
  EXPECT_EQ(kept(0, 1), 0.012);
}

TEST(PointCloudReductionTest, NoTwoKeptPointsAreCloserThanTheDistance) {
  const Eigen::Matrix3Xd kept = DownsampleByMinDistance(RandomCloud(3000, 1), 0.01);
  ASSERT_GT(kept.cols(), 100);
  for (Eigen::Index i = 0; i < kept.cols(); ++i) {
    for (Eigen::Index j = i + 1; j < kept.cols(); ++j) ASSERT_GE((kept.col(i) - kept.col(j)).norm(), 0.01);
  }
  EXPECT_EQ(kept, DownsampleByMinDistance(RandomCloud(3000, 1), 0.01));  // deterministic
}

TEST(PointCloudReductionTest, VoxelCentroidsInFirstSeenOrder) {
  Eigen::Matrix3Xd points(3, 4);
  points << 0.15, 0.01, 0.03, 0.11,  //
      0.0, 0.0, 0.0, 0.0,            //
      0.0, 0.0, 0.0, 0.0;
  const Eigen::Matrix3Xd centroids = VoxelGridCentroids(points, 0.1);
  ASSERT_EQ(centroids.cols(), 2);
  EXPECT_DOUBLE_EQ(centroids(0, 0), 0.13);  // cell 1 first: (0.15 + 0.11) / 2
  EXPECT_DOUBLE_EQ(centroids(0, 1), 0.02);
  EXPECT_EQ(CountOccupiedVoxels(points, 0.1), 2);
  // Negative coordinates fall in their own cells (floor, not truncation).
  Eigen::Matrix3Xd straddle(3, 2);
  straddle << -0.01, 0.01, 0.0, 0.0, 0.0, 0.0;
  EXPECT_EQ(CountOccupiedVoxels(straddle, 0.1), 2);
}

TEST(PointCloudReductionTest, ReachKeepsTheBallAndDropsNaN) {
  Eigen::Matrix3Xd points(3, 3);
  points << 0.0, 0.0, std::numeric_limits<double>::quiet_NaN(),  //
      0.0, 0.0, 0.0,                                             //
      0.5, 1.5, 0.5;
  const Eigen::Matrix3Xd kept = KeepWithinReach(points, Eigen::Vector3d::Zero(), 1.0);
  ASSERT_EQ(kept.cols(), 1);
  EXPECT_EQ(kept(2, 0), 0.5);
}

TEST(PointCloudReductionTest, BadInputNamesTheValue) {
  const Eigen::Matrix3Xd points = RandomCloud(5, 2);
  CAIRN_EXPECT_THROWS_WITH(DownsampleByMinDistance(points, 0.0), std::invalid_argument,
                           "down-sampling distance is 0 m");
  CAIRN_EXPECT_THROWS_WITH(VoxelGridCentroids(points, -1.0), std::invalid_argument, "voxel size is -1 m");
  Eigen::Matrix3Xd far = points;
  far(0, 3) = 1e9;
  CAIRN_EXPECT_THROWS_WITH(VoxelGridCentroids(far, 0.01), std::invalid_argument, "point 3 (1e+09", "2^20 cells");
  far(0, 3) = std::numeric_limits<double>::infinity();
  CAIRN_EXPECT_THROWS_WITH(DownsampleByMinDistance(far, 0.01), std::invalid_argument, "point 3", "not finite");
  CAIRN_EXPECT_THROWS_WITH(KeepWithinReach(points, Eigen::Vector3d::Zero(), -2.0), std::invalid_argument,
                           "reach radius is -2 m");
}

}  // namespace
}  // namespace cairn::perception
