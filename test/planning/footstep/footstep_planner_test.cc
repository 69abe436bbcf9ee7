#include <cairn/planning/footstep/footstep_planner.h>

#include <memory>

#include <gtest/gtest.h>

#include "expect_throws.h"
#include "test_step_cost_model.h"

namespace cairn::planning {
namespace {

TerrainMap Ground() {
  TerrainMap map(Eigen::Vector2d(-0.5, -1.0), 100, 80, 0.025);
  for (int r = 0; r < map.rows(); ++r) {
    for (int c = 0; c < map.cols(); ++c) map.SetCell(c, r, 0.0, Eigen::Vector3d::UnitZ(), 1.0);
  }
  return map;
}

TEST(FootstepPlannerTest, DeclaresItsPortsAndPlansFromItsInputs) {
  auto model = std::make_shared<test::TestStepCostModel>();
  FootstepPlannerOptions options;
  options.search.time_limit = 30.0;
  const FootstepPlanner planner(model, BipedGeometry{}, options);
  EXPECT_EQ(planner.num_input_ports(), 3);
  EXPECT_EQ(planner.num_output_ports(), 1);
  auto context = planner.CreateDefaultContext();
  Stance start;
  start.left = FootPose{0.0, 0.1, 0.0, 0.0};
  start.right = FootPose{0.0, -0.1, 0.0, 0.0};
  StanceGoal goal;
  goal.stance = start;
  goal.stance.left.x = goal.stance.right.x = 1.0;
  planner.get_terrain_input_port().FixValue(context.get(), Ground());
  planner.get_start_input_port().FixValue(context.get(), start);
  planner.get_goal_input_port().FixValue(context.get(), goal);
  const FootstepPlan plan = planner.get_plan_output_port().Eval<FootstepPlan>(*context);  // a copy: the cache changes below
  ASSERT_TRUE(plan.found) << plan.reason;
  EXPECT_GE(plan.steps.size(), 3u);
  EXPECT_EQ(plan.cost_model, "test cost model");
  // Cached: a second evaluation prices no step.
  const long evaluations = model->evaluations;
  planner.get_plan_output_port().Eval<FootstepPlan>(*context);
  EXPECT_EQ(model->evaluations, evaluations);
  // A new goal replans.
  goal.stance.left.x = goal.stance.right.x = 0.5;
  planner.get_goal_input_port().FixValue(context.get(), goal);
  const FootstepPlan& shorter = planner.get_plan_output_port().Eval<FootstepPlan>(*context);
  ASSERT_TRUE(shorter.found);
  EXPECT_LT(shorter.cost, plan.cost);
}

TEST(FootstepPlannerTest, RejectsANullCostModel) {
  CAIRN_EXPECT_THROWS_WITH(FootstepPlanner(nullptr, BipedGeometry{}, FootstepPlannerOptions{}), std::invalid_argument,
                           "the step cost model is null");
}

}  // namespace
}  // namespace cairn::planning
