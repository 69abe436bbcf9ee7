#include <cairn/planning/footstep/terrain_map.h>

#include <cmath>

#include <gtest/gtest.h>

#include "expect_throws.h"

namespace cairn::planning {
namespace {

TEST(TerrainMapTest, CellsStartWithoutGroundAndKeepWhatIsSet) {
  TerrainMap map(Eigen::Vector2d(-1.0, -2.0), 40, 80, 0.05);
  EXPECT_DOUBLE_EQ(map.max_corner().x(), 1.0);
  EXPECT_DOUBLE_EQ(map.max_corner().y(), 2.0);
  int col, row;
  ASSERT_TRUE(map.CellAt(0.0, 0.0, &col, &row));
  EXPECT_EQ(col, 20);
  EXPECT_EQ(row, 40);
  EXPECT_FALSE(map.has_ground(col, row));
  EXPECT_FALSE(map.walkable(col, row));
  const Eigen::Vector3d n = Eigen::Vector3d(0.1, 0.0, 1.0).normalized();
  map.SetCell(col, row, 0.3, n, 0.6);
  EXPECT_TRUE(map.walkable(col, row));
  EXPECT_FLOAT_EQ(map.height(col, row), 0.3f);
  EXPECT_NEAR((map.normal(col, row) - n).norm(), 0.0, 1e-6);
  map.SetCell(col, row, 0.3, n, 0.0);
  EXPECT_TRUE(map.has_ground(col, row));
  EXPECT_FALSE(map.walkable(col, row));
  EXPECT_FALSE(map.CellAt(1.0, 0.0, &col, &row));
  EXPECT_FALSE(map.CellAt(-1.01, 0.0, &col, &row));
}

TEST(TerrainMapTest, ObstaclesRemoveGroundUnderThemAndCollideWithBoxes) {
  TerrainMap map(Eigen::Vector2d(0.0, 0.0), 40, 40, 0.05);
  for (int r = 0; r < 40; ++r) {
    for (int c = 0; c < 40; ++c) map.SetCell(c, r, 0.0, Eigen::Vector3d::UnitZ(), 1.0);
  }
  TerrainMap::Obstacle wall{"wall", Eigen::Vector3d(1.0, 1.0, 0.5), Eigen::Vector3d(0.1, 0.5, 0.5), M_PI / 4};
  map.AddObstacle(wall);
  int col, row;
  ASSERT_TRUE(map.CellAt(1.0, 1.0, &col, &row));
  EXPECT_FALSE(map.has_ground(col, row));
  ASSERT_TRUE(map.CellAt(1.2, 1.2, &col, &row));  // 0.3 m across the wall's thin axis: outside
  EXPECT_TRUE(map.has_ground(col, row));
  ASSERT_TRUE(map.CellAt(0.8, 1.2, &col, &row));  // 0.28 m along the rotated long axis: inside
  EXPECT_FALSE(map.has_ground(col, row));
  EXPECT_TRUE(map.BoxHitsObstacle(Eigen::Vector3d(1.0, 1.0, 0.5), Eigen::Vector3d(0.05, 0.05, 0.05), 0.0));
  EXPECT_FALSE(map.BoxHitsObstacle(Eigen::Vector3d(1.0, 1.0, 1.2), Eigen::Vector3d(0.05, 0.05, 0.15), 0.0));
  EXPECT_FALSE(map.BoxHitsObstacle(Eigen::Vector3d(1.6, 0.4, 0.5), Eigen::Vector3d(0.1, 0.1, 0.1), 0.0));
}

// The free probability of a box is the product of (1 - p) over the voxels overlapping it, whatever bucket or
// side of the grid they lie in; a voxel only touching the box does not count.
TEST(TerrainMapTest, BoxFreeProbabilityMultipliesTheOverlappingVoxels) {
  TerrainMap map(Eigen::Vector2d(0.0, 0.0), 40, 40, 0.05);  // 2 m x 2 m
  const Eigen::Vector3d half(0.15, 0.25, 0.35);
  EXPECT_EQ(map.BoxFreeProbability(Eigen::Vector3d(1.0, 1.0, 0.8), half, 0.0), 1.0);
  map.SetOccupiedVoxels({{Eigen::Vector3d(1.0, 1.0, 0.8), 0.3},
                         {Eigen::Vector3d(1.1, 1.2, 0.6), 0.5},
                         {Eigen::Vector3d(1.175, 1.0, 0.8), 0.9},   // touches the face x = 1.15 only
                         {Eigen::Vector3d(-0.05, 1.0, 0.8), 0.8},   // outside the map
                         {Eigen::Vector3d(1.0, 1.0, 2.0), 0.99}},   // above the box
                        0.05);
  EXPECT_EQ(map.occupied_voxels().size(), 5u);
  EXPECT_DOUBLE_EQ(map.voxel_size(), 0.05);
  EXPECT_NEAR(map.BoxFreeProbability(Eigen::Vector3d(1.0, 1.0, 0.8), half, 0.0), 0.7 * 0.5, 1e-12);
  // Turned by 90 degrees the box reaches x = 1.25 but only y = 1.15: the 0.9 voxel counts, the 0.5 one not.
  EXPECT_NEAR(map.BoxFreeProbability(Eigen::Vector3d(1.0, 1.0, 0.8), half, M_PI / 2), 0.7 * 0.1, 1e-9);
  // The voxel outside the map still counts for a box that reaches it.
  EXPECT_NEAR(map.BoxFreeProbability(Eigen::Vector3d(0.1, 1.0, 0.8), half, 0.0), 0.2, 1e-12);
  // Stopping early: the product stops below 0.6, after the first voxel that takes it there.
  EXPECT_LT(map.BoxFreeProbability(Eigen::Vector3d(1.0, 1.0, 0.8), half, 0.0, 0.6), 0.6);
  // For bounds: only voxels that alone leave less than `free_below` count.
  EXPECT_TRUE(map.DiscMeetsVoxel(Eigen::Vector2d(1.0, 1.0), 0.1, 0.7, 0.9, 0.8));   // 1 - 0.3 < 0.8
  EXPECT_FALSE(map.DiscMeetsVoxel(Eigen::Vector2d(1.0, 1.0), 0.1, 0.7, 0.9, 0.5));  // the 0.9 voxel is 0.15 away
  EXPECT_TRUE(map.DiscMeetsVoxel(Eigen::Vector2d(1.0, 1.0), 0.2, 0.7, 0.9, 0.5));
  EXPECT_FALSE(map.DiscMeetsVoxel(Eigen::Vector2d(1.0, 1.0), 0.2, 0.9, 1.5, 0.5));  // above it
  map.SetOccupiedVoxels({}, 0.05);
  EXPECT_EQ(map.BoxFreeProbability(Eigen::Vector3d(1.0, 1.0, 0.8), half, 0.0), 1.0);
  CAIRN_EXPECT_THROWS_WITH(map.SetOccupiedVoxels({{Eigen::Vector3d::Zero(), 0.4}, {Eigen::Vector3d::Zero(), 0.0}}, 0.05),
                           std::invalid_argument, "voxel 1", "probability 0", "in (0, 1]");
  // Certainly occupied (a grid whose clamp allows probability 1): the box is certainly not free.
  map.SetOccupiedVoxels({{Eigen::Vector3d(1.0, 1.0, 0.8), 1.0}}, 0.05);
  EXPECT_EQ(map.BoxFreeProbability(Eigen::Vector3d(1.0, 1.0, 0.8), half, 0.0), 0.0);
  CAIRN_EXPECT_THROWS_WITH(map.SetOccupiedVoxels({}, 0.0), std::invalid_argument, "voxel size 0 m");
}

TEST(TerrainMapTest, RejectsBadInputNamingTheValue) {
  CAIRN_EXPECT_THROWS_WITH(TerrainMap(Eigen::Vector2d::Zero(), 0, 5, 0.05), std::invalid_argument, "0 x 5 cells");
  CAIRN_EXPECT_THROWS_WITH(TerrainMap(Eigen::Vector2d::Zero(), 100000, 100000, 0.05), std::invalid_argument,
                           "10000000000 cells are more than the 134217728");
  CAIRN_EXPECT_THROWS_WITH(TerrainMap(Eigen::Vector2d::Zero(), 5, 5, -0.1), std::invalid_argument,
                           "resolution must be a positive length", "-0.1");
  TerrainMap map(Eigen::Vector2d::Zero(), 5, 5, 0.05);
  CAIRN_EXPECT_THROWS_WITH(map.SetCell(5, 0, 0.0, Eigen::Vector3d::UnitZ(), 1.0), std::out_of_range,
                           "cell (5, 0) is outside the 5 x 5 grid");
  CAIRN_EXPECT_THROWS_WITH(map.SetCell(0, 0, 0.0, Eigen::Vector3d(0, 0, -1), 1.0), std::invalid_argument,
                           "unit vector pointing up");
  CAIRN_EXPECT_THROWS_WITH(map.SetCell(0, 0, 0.0, Eigen::Vector3d::UnitZ(), -0.2), std::invalid_argument,
                           "friction -0.2", "0 marks ground that is not walkable");
  CAIRN_EXPECT_THROWS_WITH(map.SetCell(0, 0, NAN, Eigen::Vector3d::UnitZ(), 1.0), std::invalid_argument,
                           "use ClearCell()");
  CAIRN_EXPECT_THROWS_WITH(map.AddObstacle({"flat", Eigen::Vector3d::Zero(), Eigen::Vector3d(1, 1, 0), 0.0}),
                           std::invalid_argument, "obstacle 'flat'", "positive half extents");
}

}  // namespace
}  // namespace cairn::planning
