#include "cairn/perception/synthetic/synthetic_stereo_scene.h"

#include <gtest/gtest.h>

namespace cairn::perception {
namespace {

// Ground-truth rasterisation must be exact: a cube overlaps a box iff their extents intersect, with no
// tolerance that would fatten thin objects into neighbouring cells.
TEST(SyntheticStereoSceneTest, OccupiesCubeIsExactForBoxesAndPlanes) {
  SyntheticStereoScene scene;
  Eigen::Isometry3d X_WB = Eigen::Isometry3d::Identity();
  scene.AddBox(X_WB, Eigen::Vector3d(0.04, 0.04, 1.0), ProceduralTexture{}, 1);
  EXPECT_TRUE(scene.OccupiesCube(Eigen::Vector3d::Zero(), 0.1));
  EXPECT_TRUE(scene.OccupiesCube(Eigen::Vector3d(0.085, 0.0, 0.0), 0.1));   // reaches x = 0.035 < 0.04
  EXPECT_FALSE(scene.OccupiesCube(Eigen::Vector3d(0.1, 0.0, 0.0), 0.1));    // starts at x = 0.05 > 0.04
  EXPECT_FALSE(scene.OccupiesCube(Eigen::Vector3d(0.095, 0.095, 0.0), 0.1));
  // A box rotated 45 degrees about z reaches 0.04 * sqrt(2) along x.
  SyntheticStereoScene rotated;
  X_WB.linear() = Eigen::AngleAxisd(M_PI / 4.0, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  rotated.AddBox(X_WB, Eigen::Vector3d(0.04, 0.04, 1.0), ProceduralTexture{}, 1);
  EXPECT_TRUE(rotated.OccupiesCube(Eigen::Vector3d(0.1, 0.0, 0.0), 0.1));   // cube from 0.05 < 0.0566
  EXPECT_FALSE(rotated.OccupiesCube(Eigen::Vector3d(0.12, 0.0, 0.0), 0.1));  // cube from 0.07
  // The corner region between the rotated box's faces is empty.
  EXPECT_FALSE(rotated.OccupiesCube(Eigen::Vector3d(0.07, 0.07, 0.0), 0.04));
  SyntheticStereoScene plane;
  plane.AddPlane(Eigen::Vector3d(0.0, 0.0, 1.0), Eigen::Vector3d::UnitZ(), ProceduralTexture{}, 2);
  EXPECT_TRUE(plane.OccupiesCube(Eigen::Vector3d(5.0, -3.0, 1.04), 0.1));
  EXPECT_FALSE(plane.OccupiesCube(Eigen::Vector3d(5.0, -3.0, 1.06), 0.1));
}

}  // namespace
}  // namespace cairn::perception
