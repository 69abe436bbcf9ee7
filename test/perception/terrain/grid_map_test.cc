#include "cairn/perception/terrain/grid_map.h"

#include <cmath>

#include <gtest/gtest.h>

#include "expect_throws.h"

namespace cairn::perception {
namespace {

TEST(GridMapTest, CellsAndCentres) {
  GridMap map(Eigen::Vector2i(10, 20), 0.5, Eigen::Vector2d(1.0, 2.0));
  EXPECT_EQ(map.min_corner(), Eigen::Vector2d(-1.5, -3.0));
  Eigen::Vector2i cell;
  ASSERT_TRUE(map.CellOf(Eigen::Vector2d(-1.4, -2.9), &cell));
  EXPECT_EQ(cell, Eigen::Vector2i(0, 0));
  ASSERT_TRUE(map.CellOf(Eigen::Vector2d(3.4, 6.9), &cell));
  EXPECT_EQ(cell, Eigen::Vector2i(9, 19));
  EXPECT_FALSE(map.CellOf(Eigen::Vector2d(3.6, 0.0), &cell));
  EXPECT_FALSE(map.CellOf(Eigen::Vector2d(NAN, 0.0), &cell));
  EXPECT_TRUE(map.CellCenter(Eigen::Vector2i(0, 0)).isApprox(Eigen::Vector2d(-1.25, -2.75)));
}

TEST(GridMapTest, LayersAndErrors) {
  GridMap map(Eigen::Vector2i(4, 4), 0.1, Eigen::Vector2d::Zero());
  EXPECT_EQ(map.AddLayer("elevation"), 0);
  EXPECT_EQ(map.AddLayer("count", 0.0), 1);
  EXPECT_TRUE(std::isnan(map.at(0, 1, 1)));
  EXPECT_EQ(map.at(1, 3, 3), 0.0);
  CAIRN_EXPECT_THROWS_WITH(map.AddLayer("count"), std::invalid_argument, "'count' exists already");
  CAIRN_EXPECT_THROWS_WITH(map.LayerIndex("slope"), std::invalid_argument, "no layer named 'slope'",
                           "elevation, count");
  CAIRN_EXPECT_THROWS_WITH(GridMap(Eigen::Vector2i(0, 4), 0.1, Eigen::Vector2d::Zero()), std::invalid_argument,
                           "x size 0 cells");
  CAIRN_EXPECT_THROWS_WITH(GridMap(Eigen::Vector2i(10000, 10000), 0.1, Eigen::Vector2d::Zero()),
                           std::invalid_argument, "exceed the limit of 16777216");
  CAIRN_EXPECT_THROWS_WITH(GridMap(Eigen::Vector2i(4, 4), -1.0, Eigen::Vector2d::Zero()), std::invalid_argument,
                           "resolution -1 m");
}

// Moving keeps every cell that stays in the map at its world position (no copy: only the offset changes) and
// clears the cells that enter.
TEST(GridMapTest, MoveShiftsOffsetAndClearsLeavingCells) {
  GridMap map(Eigen::Vector2i(8, 6), 1.0, Eigen::Vector2d::Zero());
  const int layer = map.AddLayer("id");
  for (int i = 0; i < 8; ++i) {
    for (int j = 0; j < 6; ++j) {
      const Eigen::Vector2d c = map.CellCenter(Eigen::Vector2i(i, j));
      map.at(layer, i, j) = 100.0 * c.x() + c.y();
    }
  }
  const double* storage = map.layer_data(layer).data();
  for (const Eigen::Vector2d& target : {Eigen::Vector2d(2.2, -1.1), Eigen::Vector2d(-3.0, 4.0),
                                       Eigen::Vector2d(-2.9, 4.1), Eigen::Vector2d(30.0, 0.0)}) {
    const Eigen::Vector2d old_min = map.min_corner();
    const Eigen::Vector2d old_max = old_min + map.length();
    map.Move(target);
    EXPECT_EQ(map.layer_data(layer).data(), storage);  // the same buffer
    EXPECT_NEAR((map.center() - target).cwiseAbs().maxCoeff(), 0.0, 0.5 + 1e-12);
    for (int i = 0; i < 8; ++i) {
      for (int j = 0; j < 6; ++j) {
        const Eigen::Vector2d c = map.CellCenter(Eigen::Vector2i(i, j));
        const bool stayed = (c.array() > old_min.array()).all() && (c.array() < old_max.array()).all();
        const double v = map.at(layer, i, j);
        if (stayed) {
          EXPECT_DOUBLE_EQ(v, 100.0 * c.x() + c.y()) << i << "," << j;
        } else {
          EXPECT_TRUE(std::isnan(v)) << i << "," << j;
          map.at(layer, i, j) = 100.0 * c.x() + c.y();
        }
      }
    }
  }
  CAIRN_EXPECT_THROWS_WITH(map.Move(Eigen::Vector2d(INFINITY, 0.0)), std::invalid_argument, "must be finite");
}

TEST(GridMapTest, StorageIndexRoundTrips) {
  GridMap map(Eigen::Vector2i(5, 7), 0.2, Eigen::Vector2d::Zero());
  map.Move(Eigen::Vector2d(0.6, -0.4));
  for (int i = 0; i < 5; ++i) {
    for (int j = 0; j < 7; ++j) EXPECT_EQ(map.MapIndexOfStorage(map.StorageIndex(i, j)), Eigen::Vector2i(i, j));
  }
}

}  // namespace
}  // namespace cairn::perception
