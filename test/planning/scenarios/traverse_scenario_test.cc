#include "cairn/planning/scenarios/traverse_scenario.h"

#include <gtest/gtest.h>

#include "expect_throws.h"
#include "test_paths.h"

namespace cairn::planning {
namespace {

TEST(TraverseScenarioTest, ReadsTheShippedScenario) {
  const auto s = TraverseScenario::Load(std::string(CAIRN_SOURCE_DIR) + "/examples/scenarios/traverse/plants_and_water.yaml");
  ASSERT_EQ(s.regions.size(), 5u);
  EXPECT_EQ(s.regions[0].name, "soft plants");
  EXPECT_EQ(s.ClassAt(Eigen::Vector2d(3.5, 5.0)), 0);
  EXPECT_EQ(s.ClassAt(Eigen::Vector2d(6.5, 3.0)), 1);
  EXPECT_EQ(s.ClassAt(Eigen::Vector2d(1.0, 1.0)), -1);
  EXPECT_NEAR(s.TrueCollapsibility(Eigen::Vector2d(3.5, 5.0)), 0.85, 1e-12);
  EXPECT_DOUBLE_EQ(s.TrueCollapsibility(Eigen::Vector2d(6.5, 3.0)), 1.0);
  EXPECT_DOUBLE_EQ(s.TrueCollapsibility(Eigen::Vector2d(6.5, 6.0)), 0.0);
  EXPECT_GT(s.HeightAt(Eigen::Vector2d(3.1, 7.1)), 0.0);
}

TEST(TraverseScenarioTest, ErrorsNameTheLineAndKey) {
  CAIRN_EXPECT_THROWS_WITH(TraverseScenario::FromText("s.yaml", "start: [1, 1]\ngoal: [20, 1]\n"),
                           std::invalid_argument, "s.yaml", "line 2", "goal is outside the world");
  CAIRN_EXPECT_THROWS_WITH(
      TraverseScenario::FromText("s.yaml", "start: [1, 1]\ngoal: [2, 1]\nregions:\n  - {kind: lava, box: {min: [0, 0], max: [1, 1]}}\n"),
      std::invalid_argument, "line 4", "kind 'lava' is not one of rocks, plants, water");
  CAIRN_EXPECT_THROWS_WITH(
      TraverseScenario::FromText("s.yaml", "world: {resolution: 0.001, size: [100, 100]}\nstart: [1, 1]\ngoal: [2, 1]\n"),
      std::invalid_argument, "world: 'resolution' must be in [0.01, 10]");
  CAIRN_EXPECT_THROWS_WITH(
      TraverseScenario::FromText("s.yaml", "world: {resolution: 0.01, size: [100, 100]}\nstart: [1, 1]\ngoal: [2, 1]\n"),
      std::invalid_argument, "cells (size / resolution) exceed the limit of 4194304");
  CAIRN_EXPECT_THROWS_WITH(TraverseScenario::FromText("s.yaml", "start: [1, 1]\ngoal: [2, 1]\nprobe: {samples: 0}\n"),
                           std::invalid_argument, "samples");
  CAIRN_EXPECT_THROWS_WITH(TraverseScenario::FromText("s.yaml", "start: [1, 1]\ngoal: [2, 1]\nprobe: {model: rubber}\n"),
                           std::invalid_argument, "line 3", "probe: model 'rubber' is not one of plant, spring");
  CAIRN_EXPECT_THROWS_WITH(TraverseScenario::FromText("s.yaml", "start: [1, 1]\ngoal: [2, 1]\nprobe: {damping: -1}\n"),
                           std::invalid_argument, "probe: 'damping' must be in [0, 1e+06] N s/m, got -1");
}

TEST(TraverseScenarioTest, ProbeModelDefaultsToThePlant) {
  const std::string base = "start: [1, 1]\ngoal: [2, 1]\n";
  EXPECT_EQ(TraverseScenario::FromText("s.yaml", base).probe_model, TraverseScenario::ProbeModel::kPlant);
  const TraverseScenario spring = TraverseScenario::FromText("s.yaml", base + "probe: {model: spring, damping: 20}\n");
  EXPECT_EQ(spring.probe_model, TraverseScenario::ProbeModel::kSpring);
  EXPECT_EQ(spring.probe_damping, 20.0);
}

}  // namespace
}  // namespace cairn::planning
