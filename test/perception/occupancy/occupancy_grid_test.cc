#include "cairn/perception/occupancy/occupancy_grid.h"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <optional>
#include <random>
#include <stdexcept>

#include "expect_throws.h"
#include "test_paths.h"

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
  {
    std::ofstream earlier(path);
    earlier << "an earlier, longer file that WritePly replaces as a whole rather than overwriting in place\n";
  }
  grid.WritePly(path);
  std::ifstream in(path);
  std::string contents((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_THAT(contents, ::testing::HasSubstr("element vertex 1"));
  EXPECT_EQ(contents, grid.PlyText());
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

// A ray starting on a cell boundary (x = 1.7 with 0.1 m cells: the boundary computes as 1.7000000000000002) and
// almost parallel to it: that boundary's t, about -2e-16 / 1e-20, lies far outside the fixed-point range (it was
// converted out of range, undefined behaviour, before it was saturated) and behind the start.
TEST(OccupancyGridTest, TraverseHandlesARayAlongACellBoundary) {
  const OccupancyGrid grid(Eigen::Vector3d::Zero(), 0.1, Eigen::Vector3i(40, 40, 40));
  std::vector<Eigen::Vector3i> cells;
  double last_t = 0.0;
  grid.Traverse(Eigen::Vector3d(1.7, 0.55, 0.05), Eigen::Vector3d(-1e-20, 0.0, 1.0), 0.0, 10.0,
                [&](std::size_t index, double t_in, double t_out) {
                  EXPECT_DOUBLE_EQ(t_in, last_t);
                  EXPECT_GT(t_out, t_in);
                  last_t = t_out;
                  cells.push_back(grid.Cell(index));
                  return true;
                });
  ASSERT_EQ(cells.size(), 40u);  // straight up through z = 0 .. 39
  for (int z = 0; z < 40; ++z) {
    EXPECT_EQ(cells[z].z(), z);
    EXPECT_EQ(cells[z].y(), 5);
    EXPECT_TRUE(cells[z].x() == 16 || cells[z].x() == 17) << cells[z].transpose();
  }
  EXPECT_NEAR(last_t, 3.95, 1e-9);
  EXPECT_FALSE(grid.CastRay(Eigen::Vector3d(1.7, 0.55, 0.05), Eigen::Vector3d(-1e-20, 0.0, 1.0), 10.0));
}

// Through an edge (two boundaries at once) or a corner (three), the cells the ray only touches are not visited.
TEST(OccupancyGridTest, TraverseSkipsCellsTouchedOnlyAtAnEdgeOrCorner) {
  OccupancyGrid grid(Eigen::Vector3d::Zero(), 1.0, Eigen::Vector3i(4, 4, 4));
  for (const Eigen::Vector3d& direction : {Eigen::Vector3d(1.0, 1.0, 0.0), Eigen::Vector3d(1.0, 1.0, 1.0)}) {
    std::vector<Eigen::Vector3i> cells;
    double last_t = 0.0;
    grid.Traverse(Eigen::Vector3d(0.5, 0.5, 0.5), direction, 0.0, 100.0,
                  [&](std::size_t index, double t_in, double t_out) {
                    EXPECT_EQ(t_in, last_t);
                    last_t = t_out;
                    cells.push_back(grid.Cell(index));
                    return true;
                  });
    // Leaves through x = 4 at t = 3.5, having crossed the diagonal cells only.
    EXPECT_NEAR(last_t, 3.5, 1e-12);
    ASSERT_EQ(cells.size(), 4u) << direction.transpose();
    for (int i = 0; i < 4; ++i) {
      EXPECT_EQ(cells[i], Eigen::Vector3i(i, i, direction.z() > 0.0 ? i : 0)) << direction.transpose();
    }
  }
}

// Random rays from inside and outside the grid: every cell is visited once, in order, as a face neighbour of the
// previous one, over an interval whose middle lies in it; together the intervals cover the ray's part in the grid.
TEST(OccupancyGridTest, TraverseCoversTheRayCellByCell) {
  OccupancyGrid grid(Eigen::Vector3d(-1.1, 0.4, -0.7), 0.3, Eigen::Vector3i(7, 5, 9));
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  int visits = 0;
  for (int ray = 0; ray < 2000; ++ray) {
    const Eigen::Vector3d origin = grid.min_corner() + Eigen::Vector3d(1.2 + 1.6 * uniform(rng), 0.75 + uniform(rng),
                                                                       1.35 + 2.0 * uniform(rng));
    Eigen::Vector3d direction(uniform(rng), uniform(rng), uniform(rng));
    if (ray % 5 == 0) direction[ray % 3] = 0.0;  // parallel to a plane of the grid
    const double t_begin = ray % 2 == 0 ? 0.0 : -3.0;
    const double t_end = 0.5 + 4.0 * (1.0 + uniform(rng));
    // The part of [t_begin, t_end] inside the box.
    double t0 = t_begin;
    double t1 = t_end;
    for (int a = 0; a < 3; ++a) {
      if (direction[a] == 0.0) {
        if (origin[a] < grid.min_corner()[a] || origin[a] >= grid.max_corner()[a]) t1 = t0;
        continue;
      }
      const double ta = (grid.min_corner()[a] - origin[a]) / direction[a];
      const double tb = (grid.max_corner()[a] - origin[a]) / direction[a];
      t0 = std::max(t0, std::min(ta, tb));
      t1 = std::min(t1, std::max(ta, tb));
    }
    double covered = 0.0;
    double last_t = t0;
    std::optional<Eigen::Vector3i> previous;
    grid.Traverse(origin, direction, t_begin, t_end, [&](std::size_t index, double t_in, double t_out) {
      ++visits;
      EXPECT_LT(index, grid.num_cells());
      EXPECT_NEAR(t_in, last_t, 1e-12);
      EXPECT_GT(t_out, t_in);
      const Eigen::Vector3i cell = grid.Cell(index);
      if (previous) {
        EXPECT_EQ((cell - *previous).cwiseAbs().sum(), 1) << "ray " << ray;
      }
      const auto middle = grid.CellOf(origin + 0.5 * (t_in + t_out) * direction);
      if (t_out - t_in > 1e-9 && middle) {
        EXPECT_EQ(*middle, cell) << "ray " << ray;
      }
      covered += t_out - t_in;
      last_t = t_out;
      previous = cell;
      return true;
    });
    EXPECT_NEAR(covered, std::max(0.0, t1 - t0), 1e-9) << "ray " << ray;
  }
  EXPECT_GT(visits, 5000);
  // A zero direction: the ray is the point `origin`, whose cell is visited once.
  int calls = 0;
  grid.Traverse(grid.min_corner() + Eigen::Vector3d(0.45, 0.15, 0.75), Eigen::Vector3d::Zero(), 0.0, 2.0,
                [&](std::size_t index, double t_in, double t_out) {
                  ++calls;
                  EXPECT_EQ(grid.Cell(index), Eigen::Vector3i(1, 0, 2));
                  EXPECT_EQ(t_in, 0.0);
                  EXPECT_EQ(t_out, 2.0);
                  return true;
                });
  EXPECT_EQ(calls, 1);
}

TEST(OccupancyGridTest, RejectsBadConstruction) {
  CAIRN_EXPECT_THROWS_WITH(OccupancyGrid(Eigen::Vector3d::Zero(), 0.0, Eigen::Vector3i(1, 1, 1)),
                           std::invalid_argument, "resolution 0", "5 cm");
  CAIRN_EXPECT_THROWS_WITH(OccupancyGrid(Eigen::Vector3d::Zero(), 0.1, Eigen::Vector3i(1, 0, 1)),
                           std::invalid_argument, "1x0x1");
  // 2^31 - 1 cubed wrapped round size_t's checks before; now it is named with the limit.
  CAIRN_EXPECT_THROWS_WITH(OccupancyGrid(Eigen::Vector3d::Zero(), 0.1, Eigen::Vector3i::Constant(2147483647)),
                           std::invalid_argument, "2147483647x2147483647x2147483647", "more than the 1073741824");
  CAIRN_EXPECT_THROWS_WITH(OccupancyGrid(Eigen::Vector3d(0, std::nan(""), 0), 0.1, Eigen::Vector3i(1, 1, 1)),
                           std::invalid_argument, "minimum corner must be finite");
  OccupancyGrid grid(Eigen::Vector3d::Zero(), 0.1, Eigen::Vector3i(1, 1, 1));
  CAIRN_EXPECT_THROWS_WITH(grid.CastRay(Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(), 1.0),
                           std::invalid_argument, "direction is zero");
  CAIRN_EXPECT_THROWS_WITH(grid.WritePly("/nonexistent-folder/x.ply"), std::runtime_error, "/nonexistent-folder/x.ply");
}

}  // namespace
}  // namespace cairn::perception
