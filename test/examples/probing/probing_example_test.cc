#include "examples/probing/probing_example.h"

#include <gtest/gtest.h>

namespace cairn::examples {
namespace {

// The diagram does what TraverseSimulation does: probes the soft plants, the water and the hard plants, in that
// order, and walks to the goal without setting foot on collapsible ground.
TEST(ProbingExampleTest, TheDiagramProbesAndAvoidsCollapsibleGround) {
  const auto scenario =
      planning::TraverseScenario::Load(CAIRN_SOURCE_DIR "/examples/scenarios/traverse/plants_and_water.yaml");
  const ProbingRun run = RunProbingExample(scenario, 300.0);
  ASSERT_TRUE(run.reached_goal);
  ASSERT_EQ(run.probes_made, 3);
  EXPECT_GT(run.collapsibilities[0], 0.75);  // soft soil under the plants
  EXPECT_GT(run.collapsibilities[1], 0.9);   // deep water
  EXPECT_LT(run.collapsibilities[2], 0.1);   // hard soil under the other plants
  for (const Eigen::Vector2d& p : run.trajectory) EXPECT_LT(scenario.TrueCollapsibility(p), 0.5) << p.transpose();
}

}  // namespace
}  // namespace cairn::examples
