#include "cairn/planning/scenarios/probing_diagram.h"

#include <algorithm>

#include <gtest/gtest.h>

#include "expect_throws.h"
#include "test_paths.h"

namespace cairn::planning {
namespace {

const std::string kScenario = std::string(CAIRN_SOURCE_DIR) + "/examples/scenarios/traverse/plants_and_water.yaml";
const std::string kArm = std::string(CAIRN_SOURCE_DIR) + "/data/robots/cairn_probe_arm.urdf";

bool Entered(const ProbingRun& r, const std::string& name) {
  return std::find(r.regions_entered.begin(), r.regions_entered.end(), name) != r.regions_entered.end();
}

// The diagram (what `cairn traverse` runs) shows seed 001's sequence: the first plan crosses the plants on soft
// soil; the robot probes them (the arm in the physics plant), finds them collapsible and replans around; it probes
// the water and avoids it; it probes the plants on hard soil and crosses them; it reaches the goal without
// setting foot on collapsible ground.
TEST(ProbingDiagramTest, TheDiagramProbesAndAvoidsCollapsibleGround) {
  const auto scenario = TraverseScenario::Load(kScenario);
  const ProbingRun run = RunProbingDiagram(scenario, kArm, 300.0);
  ASSERT_TRUE(run.reached_goal) << run.failure;
  ASSERT_EQ(run.probes_made, 3);
  ASSERT_EQ(run.probes.size(), 3u);
  EXPECT_EQ(run.probes[0].region, "soft plants");
  EXPECT_GT(run.collapsibilities[0], 0.75);  // soft soil under the plants (about 0.85)
  EXPECT_LT(run.collapsibilities[0], 0.95);
  EXPECT_TRUE(run.probes[0].path_crossed_cluster);
  EXPECT_FALSE(run.probes[0].path_crosses_after);
  EXPECT_GE(run.replans, 1);
  EXPECT_EQ(run.probes[1].region, "deep water");
  EXPECT_GT(run.collapsibilities[1], 0.9);
  EXPECT_FALSE(run.probes[1].path_crosses_after);
  EXPECT_EQ(run.probes[2].region, "hard plants");
  EXPECT_LT(run.collapsibilities[2], 0.1);
  for (const auto& p : run.probes) EXPECT_GT(p.simulated_time, 0.0);
  EXPECT_GT(run.probe_simulated_time, 0.0);
  EXPECT_TRUE(Entered(run, "hard plants"));
  EXPECT_FALSE(Entered(run, "soft plants"));
  EXPECT_FALSE(Entered(run, "deep water"));
  EXPECT_EQ(run.collapsible_steps, 0);
  for (const Eigen::Vector2d& p : run.trajectory) EXPECT_LT(scenario.TrueCollapsibility(p), 0.5) << p.transpose();
  EXPECT_TRUE(std::any_of(run.first_path.begin(), run.first_path.end(), [](const Eigen::Vector2d& p) {
    return p.x() > 3.0 && p.x() < 4.5 && p.y() > 3.0 && p.y() < 7.0;
  }));
  EXPECT_TRUE(run.map.HasLayer("traversability"));
}

// A long probe (60 readings, 0.3 s of the 5 ms force sensor) still reads C from its whole window: the supervisor
// waits as many 0.1 s periods as the readings need (two were too few), so each probe's C is eq. 5 of the average
// of all its readings.
TEST(ProbingDiagramTest, ALongProbeIsReadFromItsWholeWindow) {
  TraverseScenario scenario = TraverseScenario::Load(kScenario);
  scenario.probe_samples = 60;
  const ProbingRun run = RunProbingDiagram(scenario, kArm, 300.0);
  ASSERT_TRUE(run.reached_goal) << run.failure;
  ASSERT_EQ(run.probes.size(), 3u);
  for (const auto& probe : run.probes) {
    // C is at most 1: over water the noisy readings may average below zero.
    const double from_average =
        std::min(std::max(scenario.hard_force - probe.average_force, 0.0) / scenario.hard_force, 1.0);
    EXPECT_NEAR(probe.collapsibility, from_average, 1e-9) << probe.region;
  }
}

// Without probing the diagram has no supervisor, arm or probe controller, and the robot walks over soft soil.
TEST(ProbingDiagramTest, WithoutProbingTheRobotStepsOnSoftSoil) {
  const auto scenario = TraverseScenario::Load(kScenario);
  const auto diagram = BuildProbingDiagram(scenario, kArm, false);
  for (const systems::System* system : diagram->GetSystems()) EXPECT_NE(system->get_name(), "arm");
  const ProbingRun run = RunProbingDiagram(scenario, kArm, 300.0, false);
  EXPECT_TRUE(run.probes.empty());
  EXPECT_TRUE(Entered(run, "soft plants"));
  EXPECT_GT(run.collapsible_steps, 0);
}

TEST(ProbingDiagramTest, BadArgumentsAreRefused) {
  const auto scenario = TraverseScenario::Load(kScenario);
  CAIRN_EXPECT_THROWS_WITH(RunProbingDiagram(scenario, kArm, -1.0), std::invalid_argument, "max_time -1 s");
  CAIRN_EXPECT_THROWS_WITH(BuildProbingDiagram(scenario, ""), std::invalid_argument, "no probe arm URDF was given");
}

}  // namespace
}  // namespace cairn::planning
