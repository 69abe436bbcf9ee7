#include <cairn/planning/footstep/footstep_planner.h>

#include <limits>
#include <memory>

#include <gtest/gtest.h>

#include <cairn/systems/analysis/simulator.h>

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
  // Nothing is searched until an event asks for it.
  EXPECT_FALSE(planner.get_plan_output_port().Eval<FootstepPlan>(*context).found);
  EXPECT_EQ(model->evaluations, 0);
  planner.ExecuteForcedEvents(context.get());
  const FootstepPlan plan = planner.get_plan_output_port().Eval<FootstepPlan>(*context);  // a copy: the state changes below
  ASSERT_TRUE(plan.found) << plan.reason;
  EXPECT_GE(plan.steps.size(), 3u);
  EXPECT_EQ(plan.cost_model, "test cost model");
  // The plan is state: evaluating the output again, or changing an input, searches nothing.
  const long evaluations = model->evaluations;
  planner.get_plan_output_port().Eval<FootstepPlan>(*context);
  goal.stance.left.x = goal.stance.right.x = 0.5;
  planner.get_goal_input_port().FixValue(context.get(), goal);
  EXPECT_EQ(planner.get_plan_output_port().Eval<FootstepPlan>(*context).cost, plan.cost);
  EXPECT_EQ(model->evaluations, evaluations);
  // The next event replans to the new goal.
  planner.ExecuteForcedEvents(context.get());
  const FootstepPlan& shorter = planner.get_plan_output_port().Eval<FootstepPlan>(*context);
  ASSERT_TRUE(shorter.found);
  EXPECT_LT(shorter.cost, plan.cost);
}

// With a period, a simulation replans on its own: the goal moved at t = 0.5 s is planned for by the update at
// t = 1 s (an update due at t opens the step from t, so it shows once the simulation passes t).
TEST(FootstepPlannerTest, ReplansPeriodicallyInASimulation) {
  auto model = std::make_shared<test::TestStepCostModel>();
  FootstepPlannerOptions options;
  options.search.time_limit = std::numeric_limits<double>::infinity();
  options.search.max_expansions = 200000;
  const FootstepPlanner planner(model, BipedGeometry{}, options, nullptr, WalkingObjective::kComWorkPlusHeat, 1.0);
  systems::Simulator simulator(planner);
  Stance start;
  start.left = FootPose{0.0, 0.1, 0.0, 0.0};
  start.right = FootPose{0.0, -0.1, 0.0, 0.0};
  StanceGoal goal;
  goal.stance = start;
  goal.stance.left.x = goal.stance.right.x = 1.0;
  systems::Context& context = simulator.get_mutable_context();
  planner.get_terrain_input_port().FixValue(&context, Ground());
  planner.get_start_input_port().FixValue(&context, start);
  planner.get_goal_input_port().FixValue(&context, goal);
  simulator.Initialize();
  const double first = planner.get_plan_output_port().Eval<FootstepPlan>(simulator.get_context()).cost;
  simulator.AdvanceTo(0.5);
  goal.stance.left.x = goal.stance.right.x = 0.5;
  planner.get_goal_input_port().FixValue(&simulator.get_mutable_context(), goal);
  EXPECT_EQ(planner.get_plan_output_port().Eval<FootstepPlan>(simulator.get_context()).cost, first);
  simulator.AdvanceTo(1.5);
  EXPECT_LT(planner.get_plan_output_port().Eval<FootstepPlan>(simulator.get_context()).cost, first);
  CAIRN_EXPECT_THROWS_WITH(FootstepPlanner(model, BipedGeometry{}, options, nullptr,
                                           WalkingObjective::kComWorkPlusHeat, -1.0),
                           std::invalid_argument, "period -1 s must be finite and >= 0");
}

TEST(FootstepPlannerTest, RejectsANullCostModel) {
  CAIRN_EXPECT_THROWS_WITH(FootstepPlanner(nullptr, BipedGeometry{}, FootstepPlannerOptions{}), std::invalid_argument,
                           "the step cost model is null");
}

}  // namespace
}  // namespace cairn::planning
