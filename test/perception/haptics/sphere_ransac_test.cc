#include "cairn/perception/haptics/sphere_ransac.h"

#include <cmath>
#include <random>
#include <stdexcept>

#include "expect_throws.h"

namespace cairn::perception {
namespace {

// The half of a sphere facing the origin (what a depth sensor at the origin sees), plus a plane of clutter.
Eigen::Matrix3Xd TipAndClutter(const Eigen::Vector3d& center, double radius, int sphere_points, int clutter) {
  std::mt19937 rng(7);
  std::normal_distribution<double> normal(0.0, 1.0);
  std::uniform_real_distribution<double> u(-0.2, 0.2);
  Eigen::Matrix3Xd points(3, sphere_points + clutter);
  int n = 0;
  while (n < sphere_points) {
    Eigen::Vector3d d(normal(rng), normal(rng), normal(rng));
    d.normalize();
    if (d.dot(center) > 0.0) continue;  // the far side is hidden
    points.col(n++) = center + radius * d;
  }
  for (int i = 0; i < clutter; ++i) points.col(n++) = Eigen::Vector3d(u(rng), u(rng), 1.2);
  return points;
}

TEST(SphereRansacTest, SphereThroughFourPointsByHand) {
  Eigen::Vector3d center;
  double radius = 0.0;
  ASSERT_TRUE(SphereRansac::SphereThrough(Eigen::Vector3d(1, 0, 0), Eigen::Vector3d(-1, 0, 0),
                                          Eigen::Vector3d(0, 1, 0), Eigen::Vector3d(0, 0, 1), &center, &radius));
  EXPECT_NEAR(center.norm(), 0.0, 1e-12);
  EXPECT_NEAR(radius, 1.0, 1e-12);
  // Four coplanar points define no sphere.
  EXPECT_FALSE(SphereRansac::SphereThrough(Eigen::Vector3d(1, 0, 0), Eigen::Vector3d(-1, 0, 0),
                                           Eigen::Vector3d(0, 1, 0), Eigen::Vector3d(0, -1, 0), &center, &radius));
}

TEST(SphereRansacTest, FindsTheTipAmongClutterDeterministically) {
  const Eigen::Vector3d center(0.05, -0.02, 0.8);
  const Eigen::Matrix3Xd points = TipAndClutter(center, 0.02, 150, 150);
  const SphereRansac ransac;
  const SphereFit fit = ransac.Fit(points);
  EXPECT_NEAR((fit.center - center).norm(), 0.0, 1e-6);
  EXPECT_NEAR(fit.radius, 0.02, 1e-6);
  EXPECT_EQ(fit.inliers.size(), 150u);
  EXPECT_EQ(fit.inliers.back(), 149);
  // The visible half's centroid lies in front of the centre, towards the sensor, by r/2.
  EXPECT_NEAR((fit.inlier_centroid - center).norm(), 0.01, 2e-3);
  EXPECT_LT(fit.inlier_centroid.norm(), center.norm());
  const SphereFit again = ransac.Fit(points);
  EXPECT_EQ(again.center, fit.center);
  EXPECT_EQ(again.inliers, fit.inliers);
}

TEST(SphereRansacTest, BadInputNamesTheValue) {
  SphereRansac::Options options;
  options.iterations = 0;
  CAIRN_EXPECT_THROWS_WITH(SphereRansac{options}, std::invalid_argument, "iterations is 0");
  options = {};
  options.max_radius = 0.001;
  CAIRN_EXPECT_THROWS_WITH(SphereRansac{options}, std::invalid_argument, "radius bounds [0.005, 0.001]");
  const SphereRansac ransac;
  CAIRN_EXPECT_THROWS_WITH(ransac.Fit(Eigen::Matrix3Xd::Zero(3, 3)), std::invalid_argument, "cloud has 3");
  // A plane holds no sphere of at most 10 cm radius.
  Eigen::Matrix3Xd plane(3, 100);
  for (int i = 0; i < 100; ++i) plane.col(i) = Eigen::Vector3d(0.01 * (i % 10), 0.01 * (i / 10), 1.0);
  CAIRN_EXPECT_THROWS_WITH(ransac.Fit(plane), std::runtime_error, "no sphere with a radius in [0.005, 0.1]",
                           "500 RANSAC hypotheses over 100 points");
}

}  // namespace
}  // namespace cairn::perception
