#include "cairn/perception/haptics/gist_change_detector.h"

#include <stdexcept>

#include "expect_throws.h"

namespace cairn::perception {
namespace {

// n points, two per 1 cm voxel, plus `singles` points alone in their voxels.
Eigen::Matrix3Xd Cloud(int pairs, int singles) {
  Eigen::Matrix3Xd points(3, 2 * pairs + singles);
  int n = 0;
  for (int i = 0; i < pairs; ++i) {
    points.col(n++) = Eigen::Vector3d(0.005 + 0.01 * i, 0.005, 1.005);
    points.col(n++) = Eigen::Vector3d(0.006 + 0.01 * i, 0.006, 1.006);
  }
  for (int i = 0; i < singles; ++i) points.col(n++) = Eigen::Vector3d(0.005 + 0.01 * i, 0.105, 1.005);
  return points;
}

TEST(GistChangeDetectorTest, GistIsVoxelsOverPoints) {
  EXPECT_DOUBLE_EQ(GistChangeDetector::Gist(Cloud(2, 2), 0.01), 4.0 / 6.0);
  EXPECT_DOUBLE_EQ(GistChangeDetector::Gist(Cloud(12, 1), 0.01), 13.0 / 25.0);
  EXPECT_EQ(GistChangeDetector::Gist(Eigen::Matrix3Xd(3, 0), 0.01), 0.0);
}

TEST(GistChangeDetectorTest, ChangeWhenTheDifferenceExceedsOmega) {
  GistChangeDetector detector;  // ω = 0.03, voxel 0.01
  EXPECT_EQ(detector.options().omega, 0.03);
  CAIRN_EXPECT_THROWS_WITH(detector.Compare(Cloud(1, 0)), std::logic_error, "before SetReference");
  detector.SetReference(Cloud(10, 0));  // 0.5
  EXPECT_DOUBLE_EQ(detector.reference_gist(), 0.5);
  const GistChangeDetector::Result same = detector.Compare(Cloud(12, 1));  // 0.52
  EXPECT_NEAR(same.difference, 0.02, 1e-12);
  EXPECT_FALSE(same.changed);
  const GistChangeDetector::Result changed = detector.Compare(Cloud(10, 2));  // 12 / 22 = 0.545
  EXPECT_NEAR(changed.difference, 12.0 / 22.0 - 0.5, 1e-12);
  EXPECT_TRUE(changed.changed);
  EXPECT_TRUE(detector.Compare(Eigen::Matrix3Xd(3, 0)).changed);  // open space
}

TEST(GistChangeDetectorTest, BadInputNamesTheValue) {
  GistChangeDetector::Options options;
  options.omega = -0.1;
  CAIRN_EXPECT_THROWS_WITH(GistChangeDetector{options}, std::invalid_argument, "omega is -0.1");
  options = {};
  options.voxel = 0.0;
  CAIRN_EXPECT_THROWS_WITH(GistChangeDetector{options}, std::invalid_argument, "gist voxel is 0 m");
  GistChangeDetector detector;
  CAIRN_EXPECT_THROWS_WITH(detector.SetReferenceGist(1.5), std::invalid_argument, "reference gist is 1.5");
}

}  // namespace
}  // namespace cairn::perception
