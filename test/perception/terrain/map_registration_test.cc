#include "cairn/perception/terrain/map_registration.h"

#include <cmath>

#include <gtest/gtest.h>

#include "expect_throws.h"

namespace cairn::perception {
namespace {

// A local map registered twice at different positions: overlapping global cells fuse both, with the constant
// layer variance and with the per-cell variance layer.
TEST(MapRegistrationTest, FusesLocalLayersIntoTheGlobalMap) {
  GridMap global(Eigen::Vector2i(20, 20), 0.1, Eigen::Vector2d::Zero());
  MapRegistration registration({{"traversability", "traversability", 0.2, ""},
                                {"elevation", "elevation", 0.0, "elevation_variance"}},
                               2);
  registration.AddLayers(&global);
  GridMap local(Eigen::Vector2i(10, 10), 0.1, Eigen::Vector2d(-0.2, 0.0));
  const int t = local.AddLayer("traversability", 0.9);
  local.AddLayer("elevation", 0.1);
  local.AddLayer("elevation_variance", 0.01);
  registration.Register(local, &global);
  local.Move(Eigen::Vector2d(0.2, 0.0));
  local.Fill(t, 0.5);
  local.Fill(local.LayerIndex("elevation"), 0.3);
  local.Fill(local.LayerIndex("elevation_variance"), 0.03);
  registration.Register(local, &global);
  const Eigen::Vector2d both(0.05, 0.05), first(-0.55, 0.05), outside(0.85, 0.85);
  EXPECT_DOUBLE_EQ(global.ValueAt("traversability", first), 0.9);
  EXPECT_DOUBLE_EQ(global.ValueAt("traversability", both), 0.7);  // equal variances: the average
  EXPECT_DOUBLE_EQ(global.ValueAt("traversability_variance", both), 0.1);
  EXPECT_NEAR(global.ValueAt("elevation", both), (0.03 * 0.1 + 0.01 * 0.3) / 0.04, 1e-15);
  EXPECT_NEAR(global.ValueAt("elevation_variance", both), 0.01 * 0.03 / 0.04, 1e-15);
  EXPECT_TRUE(std::isnan(global.ValueAt("traversability", outside)));
  GridMap bare(Eigen::Vector2i(2, 2), 0.1, Eigen::Vector2d::Zero());
  CAIRN_EXPECT_THROWS_WITH(registration.Register(bare, &global), std::invalid_argument,
                           "no layer named 'traversability'");
  CAIRN_EXPECT_THROWS_WITH(MapRegistration({{"a", "a", 0.0, ""}}), std::invalid_argument, "variance 0 of layer 'a'");
}

}  // namespace
}  // namespace cairn::perception
