#include "cairn/planning/scenarios/traverse_simulation.h"

#include <algorithm>

#include <gtest/gtest.h>

#include "cairn/perception/terrain/traversability_class.h"
#include "expect_throws.h"
#include "test_paths.h"

namespace cairn::planning {
namespace {

const std::string kScenario = std::string(CAIRN_SOURCE_DIR) + "/examples/scenarios/traverse/plants_and_water.yaml";
const std::string kArm = std::string(CAIRN_SOURCE_DIR) + "/data/robots/cairn_probe_arm.urdf";

TraverseSimulation::Options WithArm() {
  TraverseSimulation::Options options;
  options.probe_arm_urdf = kArm;
  return options;
}

bool Entered(const TraverseSimulation::Result& r, const std::string& name) {
  return std::find(r.regions_entered.begin(), r.regions_entered.end(), name) != r.regions_entered.end();
}

// The behaviour of seed 001 §6.1 (Fig. 6): the first path crosses the plants; the robot probes them, finds soft
// soil and replans around; it probes the water and avoids it; it probes the plants on hard soil and crosses
// them; it reaches the goal without stepping on collapsible ground. The probe forces come from the arm in the
// physics plant (the scenario's default probe model).
TEST(TraverseSimulationTest, ProbingAvoidsSoftSoilAndDeepWater) {
  const TraverseSimulation::Result r = TraverseSimulation(TraverseScenario::Load(kScenario), WithArm()).Run();
  ASSERT_TRUE(r.reached_goal) << r.failure;
  EXPECT_EQ(r.collapsible_steps, 0);
  ASSERT_GE(r.probes.size(), 3u);
  // First probe: the soft plants, which the path crossed before and avoids after.
  EXPECT_EQ(r.probes[0].region, "soft plants");
  EXPECT_TRUE(r.probes[0].path_crossed_cluster);
  EXPECT_GT(r.probes[0].collapsibility, 0.75);
  EXPECT_LT(r.probes[0].collapsibility, 0.95);  // soft soil still carries some load (C about 0.85)
  for (const auto& p : r.probes) EXPECT_GT(p.simulated_time, 0.0);
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
  TraverseSimulation::Options options = WithArm();
  options.probing = false;
  const TraverseSimulation::Result r = TraverseSimulation(TraverseScenario::Load(kScenario), options).Run();
  EXPECT_TRUE(r.probes.empty());
  EXPECT_TRUE(Entered(r, "soft plants"));
  EXPECT_GT(r.collapsible_steps, 0);
}

// The spring model, kept as the fast option, gives the same sequence of decisions.
TEST(TraverseSimulationTest, SpringProbeModelGivesTheSameDecisions) {
  TraverseScenario scenario = TraverseScenario::Load(kScenario);
  scenario.probe_model = TraverseScenario::ProbeModel::kSpring;
  const TraverseSimulation::Result r = TraverseSimulation(scenario, {}).Run();
  ASSERT_TRUE(r.reached_goal) << r.failure;
  EXPECT_EQ(r.collapsible_steps, 0);
  ASSERT_GE(r.probes.size(), 3u);
  EXPECT_EQ(r.probes[0].region, "soft plants");
  for (const auto& p : r.probes) EXPECT_EQ(p.simulated_time, 0.0);
}

TEST(TraverseSimulationTest, PlantProbeModelNeedsTheArm) {
  const TraverseScenario scenario = TraverseScenario::Load(kScenario);
  CAIRN_EXPECT_THROWS_WITH(TraverseSimulation(scenario, {}), std::invalid_argument, "no probe arm URDF was given");
  TraverseScenario far = scenario;
  far.reach = 3.0;
  CAIRN_EXPECT_THROWS_WITH(TraverseSimulation(far, WithArm()), std::invalid_argument,
                           "probe reach 3 m plus one robot step", "exceeds the arm's reach");
}

}  // namespace
}  // namespace cairn::planning
