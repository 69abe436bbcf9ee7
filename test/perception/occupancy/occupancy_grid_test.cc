#include "cairn/perception/occupancy/occupancy_grid.h"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <stdexcept>

#include "expect_throws.h"

namespace cairn::perception {
namespace {

TEST(OccupancyGridTest, IndexingUpdateClampAndQueries) {
  OccupancyGrid grid(Eigen::Vector3d(-1.0, 0.0, 0.0), 0.5, Eigen::Vector3i(4, 3, 2));
  EXPECT_EQ(grid.num_cells(), 24u);
  const auto cell = grid.CellOf(Eigen::Vector3d(0.2, 1.2, 0.7));
  ASSERT_TRUE(cell.has_value());
  EXPECT_EQ(*cell, Eigen::Vector3i(2, 2, 1));
  EXPECT_EQ(grid.Cell(grid.Index(*cell)), *cell);
  EXPECT_FALSE(grid.CellOf(Eigen::Vector3d(1.1, 0.0, 0.0)).has_value());
  EXPECT_EQ(grid.Probability(Eigen::Vector3d(5.0, 5.0, 5.0)), 0.5);
  const std::size_t i = grid.Index(*cell);
  grid.Update(i, 1.0f);
  EXPECT_NEAR(grid.probability(i), 1.0 / (1.0 + std::exp(-1.0)), 1e-6);
  for (int n = 0; n < 100; ++n) grid.Update(i, 1.0f);
  EXPECT_NEAR(grid.probability(i), 0.97, 1e-3);  // clamped
  EXPECT_EQ(grid.OccupiedCells(), std::vector<std::size_t>{i});
  const auto hit = grid.CastRay(Eigen::Vector3d(-0.9, 1.25, 0.75), Eigen::Vector3d(1.0, 0.0, 0.0), 5.0);
  ASSERT_TRUE(hit.has_value());
  EXPECT_TRUE(hit->isApprox(grid.CellCenter(*cell)));
  EXPECT_FALSE(grid.CastRay(Eigen::Vector3d(-0.9, 0.25, 0.25), Eigen::Vector3d(1.0, 0.0, 0.0), 5.0).has_value());
  const std::string path = std::string(CAIRN_BINARY_DIR) + "/occupancy_grid_test.ply";
  grid.WritePly(path);
  std::ifstream in(path);
  std::string header((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_THAT(header, ::testing::HasSubstr("element vertex 1"));
  std::remove(path.c_str());
}

TEST(OccupancyGridTest, TraverseVisitsEveryCrossedCellInOrder) {
  OccupancyGrid grid(Eigen::Vector3d::Zero(), 1.0, Eigen::Vector3i(10, 10, 1));
  std::vector<std::size_t> cells;
  double last_t = -1.0;
  double covered = 0.0;
  grid.Traverse(Eigen::Vector3d(0.5, 0.5, 0.5), Eigen::Vector3d(1.0, 0.5, 0.0), 0.0, 100.0,
                [&](std::size_t index, double t_in, double t_out) {
                  EXPECT_GE(t_in, last_t);
                  last_t = t_out;
                  covered += t_out - t_in;
                  cells.push_back(index);
                  return true;
                });
  // From (0.5, 0.5) along (1, 0.5) the ray leaves at x = 10 (t = 9.5, y = 5.25): 9 x-steps and 5 y-steps.
  EXPECT_NEAR(covered, 9.5, 1e-9);
  EXPECT_EQ(cells.size(), 15u);
  EXPECT_EQ(cells.front(), grid.Index(Eigen::Vector3i(0, 0, 0)));
  EXPECT_EQ(cells.back(), grid.Index(Eigen::Vector3i(9, 5, 0)));
}

TEST(OccupancyGridTest, RejectsBadConstruction) {
  CAIRN_EXPECT_THROWS_WITH(OccupancyGrid(Eigen::Vector3d::Zero(), 0.0, Eigen::Vector3i(1, 1, 1)),
                           std::invalid_argument, "resolution 0", "5 cm");
  CAIRN_EXPECT_THROWS_WITH(OccupancyGrid(Eigen::Vector3d::Zero(), 0.1, Eigen::Vector3i(1, 0, 1)),
                           std::invalid_argument, "1x0x1");
  OccupancyGrid grid(Eigen::Vector3d::Zero(), 0.1, Eigen::Vector3i(1, 1, 1));
  CAIRN_EXPECT_THROWS_WITH(grid.CastRay(Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(), 1.0),
                           std::invalid_argument, "direction is zero");
  CAIRN_EXPECT_THROWS_WITH(grid.WritePly("/nonexistent-folder/x.ply"), std::runtime_error, "/nonexistent-folder/x.ply");
}

}  // namespace
}  // namespace cairn::perception
