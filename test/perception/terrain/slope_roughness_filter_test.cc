#include "cairn/perception/terrain/slope_roughness_filter.h"

#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "expect_throws.h"

namespace cairn::perception {
namespace {

GridMap PlaneMap(double gx, double gy) {
  GridMap map(Eigen::Vector2i(30, 24), 0.05, Eigen::Vector2d(0.3, -0.2));
  const int z = map.AddLayer("elevation");
  map.Move(Eigen::Vector2d(0.42, -0.07));  // a shifted buffer must not change the result
  for (int i = 0; i < 30; ++i) {
    for (int j = 0; j < 24; ++j) {
      const Eigen::Vector2d c = map.CellCenter(Eigen::Vector2i(i, j));
      map.at(z, i, j) = 0.4 + gx * c.x() + gy * c.y();
    }
  }
  return map;
}

TEST(SlopeRoughnessFilterTest, TiltedPlaneHasItsSlopeAndNoRoughness) {
  const double gx = 0.3, gy = -0.2;
  GridMap map = PlaneMap(gx, gy);
  SlopeRoughnessFilter::Options options;
  options.num_threads = 2;
  SlopeRoughnessFilter(options).Compute(&map);
  const double expected = std::atan(std::sqrt(gx * gx + gy * gy));
  for (int i = 0; i < 30; ++i) {
    for (int j = 0; j < 24; ++j) {  // edges included: their windows are truncated but still planar
      EXPECT_NEAR(map.at(map.LayerIndex("slope"), i, j), expected, 1e-9) << i << "," << j;
      EXPECT_NEAR(map.at(map.LayerIndex("roughness"), i, j), 0.0, 1e-9) << i << "," << j;
    }
  }
}

TEST(SlopeRoughnessFilterTest, NoisyFlatGroundHasItsNoiseAsRoughness) {
  GridMap map(Eigen::Vector2i(60, 60), 0.05, Eigen::Vector2d::Zero());
  const int z = map.AddLayer("elevation");
  std::mt19937 rng(3);
  std::normal_distribution<double> noise(0.0, 0.01);
  for (double& h : map.layer_data(z)) h = noise(rng);
  SlopeRoughnessFilter::Options options;
  options.window_radius = 3;
  SlopeRoughnessFilter(options).Compute(&map);
  double mean = 0.0;
  int count = 0;
  for (int i = 3; i < 57; ++i) {
    for (int j = 3; j < 57; ++j, ++count) mean += map.at(map.LayerIndex("roughness"), i, j);
  }
  mean /= count;
  // Residuals about a 3-parameter fit of 49 cells: E[s^2] = sigma^2 (49 - 3) / 49.
  EXPECT_NEAR(mean, 0.01 * std::sqrt(46.0 / 49.0), 0.0006);
}

TEST(SlopeRoughnessFilterTest, UnknownAndCollinearCellsAreUnknown) {
  GridMap map(Eigen::Vector2i(9, 9), 0.1, Eigen::Vector2d::Zero());
  const int z = map.AddLayer("elevation");
  for (int j = 0; j < 9; ++j) map.at(z, 4, j) = 0.1 * j;  // one line of known heights
  SlopeRoughnessFilter().Compute(&map);
  EXPECT_TRUE(std::isnan(map.at(map.LayerIndex("slope"), 4, 4)));
  EXPECT_TRUE(std::isnan(map.at(map.LayerIndex("slope"), 0, 0)));
  CAIRN_EXPECT_THROWS_WITH(SlopeRoughnessFilter(SlopeRoughnessFilter::Options{0, 5, 0}), std::invalid_argument,
                           "window_radius 0");
  CAIRN_EXPECT_THROWS_WITH(SlopeRoughnessFilter(SlopeRoughnessFilter::Options{1, 10, 0}), std::invalid_argument,
                           "min_valid_cells 10 must be in [3, 9]");
}

}  // namespace
}  // namespace cairn::perception
