// Cairn's haptics reductions against PCL's on the same clouds: voxel-grid centroids (pcl::VoxelGrid), the RANSAC
// sphere (pcl::SampleConsensusModelSphere + RandomSampleConsensus) and octree change detection
// (pcl::octree::OctreePointCloudChangeDetector), which the paper uses for the antenna-tip segmentation.

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <vector>

#include <gtest/gtest.h>
#include <pcl/filters/voxel_grid.h>
#include <pcl/octree/octree_pointcloud_changedetector.h>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>
#include <pcl/sample_consensus/ransac.h>
#include <pcl/sample_consensus/sac_model_sphere.h>

#include "cairn/perception/haptics/background_subtractor.h"
#include "cairn/perception/haptics/point_cloud_reduction.h"
#include "cairn/perception/haptics/sphere_ransac.h"

namespace cairn::perception {
namespace {

// Points inside cells of side `cell` (never within 10% of a cell face, so float rounding in PCL cannot move a
// point to another cell), as doubles holding float values so both libraries see the same coordinates.
Eigen::Matrix3Xd CellInteriorCloud(int n, double cell, int cells_per_axis, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> index(-cells_per_axis / 2, cells_per_axis / 2);
  std::uniform_real_distribution<double> offset(0.1, 0.9);
  Eigen::Matrix3Xd points(3, n);
  for (int i = 0; i < n; ++i) {
    for (int a = 0; a < 3; ++a) points(a, i) = static_cast<float>(cell * (index(rng) + offset(rng)));
  }
  return points;
}

pcl::PointCloud<pcl::PointXYZ>::Ptr ToPcl(const Eigen::Matrix3Xd& points) {
  pcl::PointCloud<pcl::PointXYZ>::Ptr cloud(new pcl::PointCloud<pcl::PointXYZ>);
  for (Eigen::Index i = 0; i < points.cols(); ++i) {
    cloud->push_back(pcl::PointXYZ(static_cast<float>(points(0, i)), static_cast<float>(points(1, i)),
                                   static_cast<float>(points(2, i))));
  }
  return cloud;
}

std::vector<std::array<double, 3>> Sorted(const Eigen::Matrix3Xd& points) {
  std::vector<std::array<double, 3>> rows;
  for (Eigen::Index i = 0; i < points.cols(); ++i) rows.push_back({points(0, i), points(1, i), points(2, i)});
  std::sort(rows.begin(), rows.end());
  return rows;
}

TEST(PclCrossCheckTest, VoxelGridCentroidsAgree) {
  const double leaf = 0.04;
  const Eigen::Matrix3Xd points = CellInteriorCloud(5000, leaf, 20, 1);
  pcl::VoxelGrid<pcl::PointXYZ> grid;
  grid.setInputCloud(ToPcl(points));
  grid.setLeafSize(static_cast<float>(leaf), static_cast<float>(leaf), static_cast<float>(leaf));
  pcl::PointCloud<pcl::PointXYZ> filtered;
  grid.filter(filtered);
  Eigen::Matrix3Xd theirs(3, static_cast<Eigen::Index>(filtered.size()));
  for (std::size_t i = 0; i < filtered.size(); ++i) {
    theirs.col(static_cast<Eigen::Index>(i)) = filtered[i].getVector3fMap().cast<double>();
  }
  const auto ours = Sorted(VoxelGridCentroids(points, leaf));
  const auto pcl_sorted = Sorted(theirs);
  ASSERT_EQ(ours.size(), pcl_sorted.size());
  for (std::size_t i = 0; i < ours.size(); ++i) {
    for (int a = 0; a < 3; ++a) ASSERT_NEAR(ours[i][a], pcl_sorted[i][a], 1e-5) << i;
  }
}

TEST(PclCrossCheckTest, RansacSpheresAgree) {
  std::mt19937 rng(3);
  std::normal_distribution<double> normal(0.0, 1.0);
  std::uniform_real_distribution<double> clutter(-0.3, 0.3);
  const Eigen::Vector3d center(0.1, -0.05, 0.9);
  const double radius = 0.02;
  Eigen::Matrix3Xd points(3, 400);
  for (int i = 0; i < 200; ++i) {
    Eigen::Vector3d d(normal(rng), normal(rng), normal(rng));
    d.normalize();
    if (d.dot(center) > 0.0) d = -d;  // the half facing the sensor
    points.col(i) = (center + radius * d + 0.0005 * Eigen::Vector3d(normal(rng), normal(rng), normal(rng)))
                        .cast<float>()
                        .cast<double>();
  }
  for (int i = 200; i < 400; ++i) points.col(i) = Eigen::Vector3d(clutter(rng), clutter(rng), 1.3);
  SphereRansac::Options options;
  options.inlier_threshold = 0.002;
  const SphereFit ours = SphereRansac(options).Fit(points);
  pcl::SampleConsensusModelSphere<pcl::PointXYZ>::Ptr model(new pcl::SampleConsensusModelSphere<pcl::PointXYZ>(ToPcl(points)));
  model->setRadiusLimits(options.min_radius, options.max_radius);
  pcl::RandomSampleConsensus<pcl::PointXYZ> ransac(model);
  ransac.setDistanceThreshold(options.inlier_threshold);
  ransac.setMaxIterations(options.iterations);
  ASSERT_TRUE(ransac.computeModel());
  Eigen::VectorXf coefficients;
  ransac.getModelCoefficients(coefficients);
  Eigen::VectorXf refined;
  std::vector<int> inliers;
  ransac.getInliers(inliers);
  model->optimizeModelCoefficients(inliers, coefficients, refined);
  EXPECT_NEAR((ours.center - refined.head<3>().cast<double>()).norm(), 0.0, 1e-3);
  EXPECT_NEAR(ours.radius, refined[3], 1e-3);
  EXPECT_NEAR((ours.center - center).norm(), 0.0, 1e-3);
  // Both find the tip's points and none of the clutter.
  EXPECT_GE(static_cast<int>(ours.inliers.size()), 190);
  EXPECT_LE(ours.inliers.back(), 199);
  EXPECT_GE(static_cast<int>(inliers.size()), 190);
}

TEST(PclCrossCheckTest, OctreeChangeDetectionAgreesWithBackgroundSubtraction) {
  const double resolution = 0.01;
  const Eigen::Matrix3Xd reference = CellInteriorCloud(3000, resolution, 60, 5);
  Eigen::Matrix3Xd scene(3, 3000 + 500);
  scene.leftCols(3000) = CellInteriorCloud(3000, resolution, 60, 5);  // the same background
  scene.rightCols(500) = CellInteriorCloud(500, resolution, 60, 6);   // and new points, some in new cells
  // Octree leaves start at the bounding box's minimum: put it on a multiple of the resolution so that its leaves
  // are Cairn's cells.
  pcl::octree::OctreePointCloudChangeDetector<pcl::PointXYZ> octree(resolution);
  octree.defineBoundingBox(-0.32, -0.32, -0.32, 0.32, 0.32, 0.32);
  octree.setInputCloud(ToPcl(reference));
  octree.addPointsFromInputCloud();
  octree.switchBuffers();
  octree.setInputCloud(ToPcl(scene));
  octree.addPointsFromInputCloud();
  std::vector<int> changed;
  octree.getPointIndicesFromNewVoxels(changed);
  Eigen::Matrix3Xd theirs(3, static_cast<Eigen::Index>(changed.size()));
  for (std::size_t i = 0; i < changed.size(); ++i) theirs.col(static_cast<Eigen::Index>(i)) = scene.col(changed[i]);
  const Eigen::Matrix3Xd ours = BackgroundSubtractor(reference, resolution).Foreground(scene);
  ASSERT_GT(ours.cols(), 0);
  EXPECT_EQ(Sorted(ours), Sorted(theirs));
}

}  // namespace
}  // namespace cairn::perception
