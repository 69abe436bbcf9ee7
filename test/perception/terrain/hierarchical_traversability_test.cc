#include "cairn/perception/terrain/hierarchical_traversability.h"

#include <cmath>

#include <gtest/gtest.h>

#include "cairn/perception/terrain/traversability_class.h"
#include "expect_throws.h"

namespace cairn::perception {
namespace {

// Four hand-built cells exercise each level of Algorithm 1 and its precedence.
TEST(HierarchicalTraversabilityTest, AlgorithmOnePrecedence) {
  GridMap map(Eigen::Vector2i(5, 1), 1.0, Eigen::Vector2d::Zero());
  const int c = map.AddLayer("collapsibility");
  const int plants = map.AddLayer("semantic_plants");
  const int water = map.AddLayer("semantic_water");
  const int slope = map.AddLayer("slope", 0.1);
  map.AddLayer("roughness", 0.01);
  // cell 0: everything known; collapsibility wins.
  map.at(c, 0, 0) = 0.9;
  map.at(plants, 0, 0) = 1.0;
  // cell 1: plants and (weaker) water, no collapsibility: plants' fixed value.
  map.at(plants, 1, 0) = 0.8;
  map.at(water, 1, 0) = 0.6;
  // cell 2: water below the threshold: geometry.
  map.at(water, 2, 0) = 0.4;
  // cell 3: water; cell 4: too steep geometry.
  map.at(water, 3, 0) = 0.7;
  map.at(slope, 4, 0) = 0.6;
  HierarchicalTraversability rule;
  rule.Compute(&map);
  const int t = map.LayerIndex("traversability");
  EXPECT_NEAR(map.at(t, 0, 0), 0.1, 1e-12);
  EXPECT_DOUBLE_EQ(map.at(t, 1, 0), 0.8);
  const double geometric = 1.0 - 0.5 * 0.1 / (M_PI / 6.0) - 0.5 * 0.01 / 0.05;
  EXPECT_NEAR(map.at(t, 2, 0), geometric, 1e-12);
  EXPECT_DOUBLE_EQ(map.at(t, 3, 0), 0.3);
  EXPECT_DOUBLE_EQ(map.at(t, 4, 0), 0.0);
  EXPECT_EQ(ClassifyTraversability(map.at(t, 0, 0)), TraversabilityClass::kSemiUntraversable);
  EXPECT_EQ(ClassifyTraversability(map.at(t, 1, 0)), TraversabilityClass::kSemiTraversable);
  EXPECT_EQ(ClassifyTraversability(map.at(t, 4, 0)), TraversabilityClass::kUntraversable);
  EXPECT_EQ(ClassifyTraversability(1.0), TraversabilityClass::kTraversable);
  EXPECT_EQ(ClassifyTraversability(0.5), TraversabilityClass::kSemiUntraversable);
  EXPECT_EQ(ClassifyTraversability(NAN), TraversabilityClass::kUnknown);
}

TEST(HierarchicalTraversabilityTest, UnknownGeometryIsUnknownAndMissingLayersAreAllowed) {
  HierarchicalTraversability rule;
  EXPECT_TRUE(std::isnan(rule.CellValue(NAN, nullptr, NAN, 0.0)));
  EXPECT_DOUBLE_EQ(rule.CellValue(NAN, nullptr, 0.0, 0.0), 1.0);
  EXPECT_DOUBLE_EQ(rule.CellValue(0.0, nullptr, NAN, NAN), 1.0);
  GridMap map(Eigen::Vector2i(2, 2), 1.0, Eigen::Vector2d::Zero());
  map.AddLayer("slope", 0.0);
  map.AddLayer("roughness", 0.0);
  rule.Compute(&map);
  EXPECT_DOUBLE_EQ(map.at(map.LayerIndex("traversability"), 1, 1), 1.0);
}

// Seed 001 §4.2 registers each cell's local traversability with the variance of the analysis that set it:
// probing below semantics (constants), geometry from the sensor model (here: the elevation's variance).
TEST(HierarchicalTraversabilityTest, EachCellsVarianceComesFromTheLevelThatSetIt) {
  HierarchicalTraversability rule;
  GridMap map(Eigen::Vector2i(5, 1), 1.0, Eigen::Vector2d::Zero());
  const int c = map.AddLayer("collapsibility");
  const int plants = map.AddLayer("semantic_plants");
  map.AddLayer("semantic_water", 0.0);
  map.AddLayer("slope", 0.0);
  const int roughness = map.AddLayer("roughness", 0.01);
  const int ev = map.AddLayer("elevation_variance");
  map.at(c, 0, 0) = 0.4;       // probed
  map.at(plants, 1, 0) = 0.9;  // plants
  map.at(ev, 2, 0) = 1e-3;     // geometry with uncertain heights
  // cell 3: geometry without a height of its own (e.g. filled by the filter's window)
  map.at(roughness, 4, 0) = NAN;  // nothing known
  rule.Compute(&map);
  const int t = map.LayerIndex("traversability");
  const int tv = map.LayerIndex("traversability_variance");
  EXPECT_DOUBLE_EQ(map.at(t, 0, 0), 0.6);
  EXPECT_DOUBLE_EQ(map.at(tv, 0, 0), rule.options().probe_variance);
  EXPECT_DOUBLE_EQ(map.at(t, 1, 0), 0.8);
  EXPECT_DOUBLE_EQ(map.at(tv, 1, 0), rule.options().semantic_variance);
  EXPECT_DOUBLE_EQ(map.at(t, 2, 0), 0.9);                 // 1 - 0.5 * 0.01 / 0.05
  EXPECT_NEAR(map.at(tv, 2, 0), 100.0 * 1e-3, 1e-15);     // (0.5 / 0.05)^2 * 1e-3
  EXPECT_DOUBLE_EQ(map.at(tv, 3, 0), rule.options().geometry_variance);
  map.at(ev, 2, 0) = 1e-6;  // well fused: the floor
  rule.Compute(&map);
  EXPECT_DOUBLE_EQ(map.at(tv, 2, 0), rule.options().geometry_variance);
  EXPECT_TRUE(std::isnan(map.at(t, 4, 0)));
  EXPECT_TRUE(std::isnan(map.at(tv, 4, 0)));
  EXPECT_LT(rule.options().probe_variance, rule.options().semantic_variance);
  EXPECT_EQ(rule.CellSource(0.4, nullptr, NAN, NAN), HierarchicalTraversability::Source::kCollapsibility);
  EXPECT_EQ(rule.CellSource(NAN, nullptr, NAN, 0.0), HierarchicalTraversability::Source::kUnknown);
}

TEST(HierarchicalTraversabilityTest, RejectsBadOptions) {
  HierarchicalTraversability::Options o;
  o.semantic_values = {{"plants", 1.2}};
  CAIRN_EXPECT_THROWS_WITH(HierarchicalTraversability{o}, std::invalid_argument,
                           "traversability 1.2 of class 'plants' must be in [0, 1]");
  o = {};
  o.critical_slope = 0.0;
  CAIRN_EXPECT_THROWS_WITH(HierarchicalTraversability{o}, std::invalid_argument, "critical slope 0 rad");
  o = {};
  o.probe_variance = -1.0;
  CAIRN_EXPECT_THROWS_WITH(HierarchicalTraversability{o}, std::invalid_argument, "probe_variance -1",
                           "positive and finite");
}

}  // namespace
}  // namespace cairn::perception
