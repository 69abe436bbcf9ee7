#include "cairn/perception/haptics/camera_antenna_calibrator.h"

#include <random>
#include <stdexcept>

#include "expect_throws.h"

namespace cairn::perception {
namespace {

Eigen::Isometry3d KnownX_AC() {
  Eigen::Isometry3d X = Eigen::Isometry3d::Identity();
  X.linear() = Eigen::AngleAxisd(0.2, Eigen::Vector3d(0, 1, 0.3).normalized()).toRotationMatrix();
  X.translation() = Eigen::Vector3d(0.05, 0.12, -0.02);
  return X;
}

// A wall 1.5 m ahead of the sensor, 5 mm grid.
Eigen::Matrix3Xd Wall() {
  Eigen::Matrix3Xd wall(3, 200 * 200);
  for (int i = 0; i < 200; ++i) {
    for (int j = 0; j < 200; ++j) wall.col(i * 200 + j) = Eigen::Vector3d(-0.5 + 0.005 * i, -0.5 + 0.005 * j, 1.5);
  }
  return wall;
}

// The wall plus the sensor-facing half of a 2 cm tip centred at p_C.
Eigen::Matrix3Xd WithTip(const Eigen::Matrix3Xd& wall, const Eigen::Vector3d& p_C, unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> normal(0.0, 1.0);
  Eigen::Matrix3Xd cloud(3, wall.cols() + 200);
  cloud.leftCols(wall.cols()) = wall;
  Eigen::Index n = wall.cols();
  while (n < cloud.cols()) {
    Eigen::Vector3d d(normal(rng), normal(rng), normal(rng));
    d.normalize();
    if (d.dot(p_C) > 0.0) continue;
    cloud.col(n++) = p_C + 0.02 * d;
  }
  return cloud;
}

TEST(CameraAntennaCalibratorTest, Table1PointsAreThePaper) {
  const Eigen::Matrix3Xd points = CameraAntennaCalibrator::Table1Points();
  ASSERT_EQ(points.cols(), 5);
  EXPECT_EQ(points.col(0), Eigen::Vector3d(-0.3, 0.1, 0.6));
  EXPECT_EQ(points.col(4), Eigen::Vector3d(-0.2, 0.1, 0.8));
}

TEST(CameraAntennaCalibratorTest, BabblingRecoversTheTransform) {
  const Eigen::Matrix3Xd wall = Wall();
  const Eigen::Isometry3d X_AC = KnownX_AC();
  const Eigen::Matrix3Xd p_A = CameraAntennaCalibrator::Table1Points();
  CameraAntennaCalibrator::Options options;
  options.use_sphere_center = true;
  CameraAntennaCalibrator centers(wall, options);
  CameraAntennaCalibrator centroids(wall);  // the paper's inlier centroid
  for (int i = 0; i < p_A.cols(); ++i) {
    const Eigen::Matrix3Xd cloud = WithTip(wall, X_AC.inverse() * Eigen::Vector3d(p_A.col(i)), 10 + i);
    const auto& observation = centers.AddObservation(p_A.col(i), cloud);
    EXPECT_EQ(observation.foreground_points, 200);
    centroids.AddObservation(p_A.col(i), cloud);
  }
  const RigidTransformFit exact = centers.Solve();
  EXPECT_TRUE(exact.X_AC.isApprox(X_AC, 1e-6));
  EXPECT_LT(exact.rms_residual, 1e-6);
  // The centroid sits about r/2 = 1 cm in front of the centre, in a direction that varies with the pose: the fit
  // absorbs most of it into the translation and leaves a residual of millimetres.
  const RigidTransformFit paper = centroids.Solve();
  EXPECT_LT(paper.rms_residual, 0.005);
  EXPECT_LT((paper.X_AC.translation() - X_AC.translation()).norm(), 0.03);
}

TEST(CameraAntennaCalibratorTest, MissingTipAndTooFewPosesAreReported) {
  const Eigen::Matrix3Xd wall = Wall();
  CameraAntennaCalibrator calibrator(wall);
  CAIRN_EXPECT_THROWS_WITH(calibrator.AddObservation(Eigen::Vector3d(0.1, 0.0, 0.6), wall), std::runtime_error,
                           "tip commanded to (0.1, 0, 0.6) left only 0 foreground points");
  CAIRN_EXPECT_THROWS_WITH(calibrator.Solve(), std::invalid_argument, "at least 3 correspondences; got 0");
  CameraAntennaCalibrator::Options options;
  options.min_inliers = 2;
  CAIRN_EXPECT_THROWS_WITH(CameraAntennaCalibrator(wall, options), std::invalid_argument, "min_inliers is 2");
}

}  // namespace
}  // namespace cairn::perception
