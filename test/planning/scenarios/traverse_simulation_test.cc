#include "cairn/planning/scenarios/traverse_simulation.h"

#include <algorithm>

#include <gtest/gtest.h>

#include "cairn/perception/terrain/traversability_class.h"
#include "expect_throws.h"

namespace cairn::planning {
namespace {

const char* const kScenario = CAIRN_SOURCE_DIR "/examples/scenarios/traverse/plants_and_water.yaml";

bool Entered(const TraverseSimulation::Result& r, const std::string& name) {
  return std::find(r.regions_entered.begin(), r.regions_entered.end(), name) != r.regions_entered.end();
}

// The behaviour of seed 001 §6.1 (Fig. 6): the first path crosses the plants; the robot probes them, finds soft
// soil and replans around; it probes the water and avoids it; it probes the plants on hard soil and crosses
// them; it reaches the goal without stepping on collapsible ground.
TEST(TraverseSimulationTest, ProbingAvoidsSoftSoilAndDeepWater) {
  const TraverseSimulation::Result r = TraverseSimulation(TraverseScenario::Load(kScenario), {}).Run();
  ASSERT_TRUE(r.reached_goal) << r.failure;
  EXPECT_EQ(r.collapsible_steps, 0);
  ASSERT_GE(r.probes.size(), 3u);
  // First probe: the soft plants, which the path crossed before and avoids after.
  EXPECT_EQ(r.probes[0].region, "soft plants");
  EXPECT_TRUE(r.probes[0].path_crossed_cluster);
  EXPECT_GT(r.probes[0].collapsibility, 0.75);
  EXPECT_FALSE(r.probes[0].path_crosses_after);
  EXPECT_GE(r.replans, 1);
  const auto water = std::find_if(r.probes.begin(), r.probes.end(), [](const auto& p) { return p.region == "deep water"; });
  ASSERT_NE(water, r.probes.end());
  EXPECT_GT(water->collapsibility, 0.9);
  EXPECT_FALSE(water->path_crosses_after);
  const auto hard = std::find_if(r.probes.begin(), r.probes.end(), [](const auto& p) { return p.region == "hard plants"; });
  ASSERT_NE(hard, r.probes.end());
  EXPECT_LT(hard->collapsibility, 0.1);
  EXPECT_TRUE(Entered(r, "hard plants"));
  EXPECT_FALSE(Entered(r, "soft plants"));
  EXPECT_FALSE(Entered(r, "deep water"));
  EXPECT_FALSE(Entered(r, "rocks north"));
  // The first plan went straight through the plants (semi-traversable before probing).
  const auto& first = r.first_path;
  EXPECT_TRUE(std::any_of(first.begin(), first.end(), [](const Eigen::Vector2d& p) {
    return p.x() > 3.0 && p.x() < 4.5 && p.y() > 3.0 && p.y() < 7.0;
  }));
}

// Without probing the semi-traversable plants look fine and the robot walks onto the soft soil beneath them: the
// failure the paper's probing prevents, counted.
TEST(TraverseSimulationTest, WithoutProbingTheRobotStepsOnSoftSoil) {
  TraverseSimulation::Options options;
  options.probing = false;
  const TraverseSimulation::Result r = TraverseSimulation(TraverseScenario::Load(kScenario), options).Run();
  EXPECT_TRUE(r.probes.empty());
  EXPECT_TRUE(Entered(r, "soft plants"));
  EXPECT_GT(r.collapsible_steps, 0);
}

}  // namespace
}  // namespace cairn::planning
