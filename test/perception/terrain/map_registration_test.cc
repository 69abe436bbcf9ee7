#include "cairn/perception/terrain/map_registration.h"

#include <cmath>

#include <gtest/gtest.h>

#include "cairn/perception/terrain/hierarchical_traversability.h"
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

// Seed 001 §4.2: the local traversability is registered with the variance of the analysis behind it, and
// "the collapsibility analysis has a lower variance (higher confidence) than the semantic analysis". A patch of
// plants seen three times (0.8) and then probed soft (C = 0.85, so 0.15) ends near the probe's value; a probed
// cell then seen as plants again barely moves.
TEST(MapRegistrationTest, ProbingOutweighsSemanticsInTheRegisteredTraversability) {
  const HierarchicalTraversability rule;
  const MapRegistration registration({{"traversability", "traversability", 0.0, "traversability_variance"}});
  const auto local_map = [&](double collapsibility) {
    GridMap local(Eigen::Vector2i(1, 1), 0.1, Eigen::Vector2d::Zero());
    local.AddLayer("semantic_plants", 0.9);
    local.AddLayer("collapsibility", collapsibility);
    rule.Compute(&local);
    return local;
  };
  const double vs = rule.options().semantic_variance, vp = rule.options().probe_variance;
  const Eigen::Vector2d cell = Eigen::Vector2d::Zero();

  GridMap seen(Eigen::Vector2i(1, 1), 0.1, Eigen::Vector2d::Zero());
  registration.AddLayers(&seen);
  for (int k = 0; k < 3; ++k) registration.Register(local_map(NAN), &seen);
  EXPECT_DOUBLE_EQ(seen.ValueAt("traversability", cell), 0.8);
  EXPECT_NEAR(seen.ValueAt("traversability_variance", cell), vs / 3, 1e-15);
  registration.Register(local_map(0.85), &seen);
  const double expected = (vp * 0.8 + vs / 3 * 0.15) / (vs / 3 + vp);
  EXPECT_NEAR(seen.ValueAt("traversability", cell), expected, 1e-12);
  EXPECT_LT(seen.ValueAt("traversability", cell), 0.5);  // semi-untraversable after one probe

  // Flat ground seen precisely many times (geometry: t = 1), then probed soft: the probe still moves the cell most
  // of the way, since the geometric rule's variance has a floor above the probe's.
  GridMap flat(Eigen::Vector2i(1, 1), 0.1, Eigen::Vector2d::Zero());
  registration.AddLayers(&flat);
  const auto geometric = [&](double collapsibility) {
    GridMap local(Eigen::Vector2i(1, 1), 0.1, Eigen::Vector2d::Zero());
    local.AddLayer("slope", 0.0);
    local.AddLayer("roughness", 0.0);
    local.AddLayer("elevation_variance", 1e-7);  // thousands of fused points
    local.AddLayer("collapsibility", collapsibility);
    rule.Compute(&local);
    return local;
  };
  registration.Register(geometric(NAN), &flat);
  EXPECT_DOUBLE_EQ(flat.ValueAt("traversability", cell), 1.0);
  registration.Register(geometric(0.85), &flat);
  const double vg = rule.options().geometry_variance;
  EXPECT_NEAR(flat.ValueAt("traversability", cell), (vp * 1.0 + vg * 0.15) / (vg + vp), 1e-12);
  EXPECT_LT(flat.ValueAt("traversability", cell), 0.5);

  GridMap probed(Eigen::Vector2i(1, 1), 0.1, Eigen::Vector2d::Zero());
  registration.AddLayers(&probed);
  registration.Register(local_map(0.85), &probed);
  registration.Register(local_map(NAN), &probed);
  EXPECT_NEAR(probed.ValueAt("traversability", cell), (vs * 0.15 + vp * 0.8) / (vs + vp), 1e-12);
  EXPECT_LT(probed.ValueAt("traversability", cell), 0.2);
}

}  // namespace
}  // namespace cairn::perception
