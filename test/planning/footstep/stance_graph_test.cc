#include <cairn/planning/footstep/stance_graph.h>

#include <cmath>

#include <gtest/gtest.h>

#include <cairn/planning/footstep/plan_footsteps.h>

#include "test_step_cost_model.h"

namespace cairn::planning {
namespace {

// Ground with a slippery strip and a step up, to exercise every part of the heuristic.
TerrainMap Terrain() {
  TerrainMap map(Eigen::Vector2d(-0.5, -1.0), 120, 80, 0.025);
  for (int r = 0; r < map.rows(); ++r) {
    for (int c = 0; c < map.cols(); ++c) {
      const Eigen::Vector2d p = map.CellCenter(c, r);
      const double mu = (p.x() > 0.6 && p.x() < 0.9) ? 0.12 : 1.0;
      map.SetCell(c, r, p.x() > 1.5 ? 0.1 : 0.0, Eigen::Vector3d::UnitZ(), mu);
    }
  }
  return map;
}

Stance StanceAt(double x) {
  Stance s;
  s.left = FootPose{x, 0.1, 0.0, 0.0};
  s.right = FootPose{x, -0.1, 0.0, 0.0};
  return s;
}

TEST(StanceGraphTest, HeuristicNeverOverestimatesTheCostToGoAlongAnOptimalPlan) {
  const TerrainMap terrain = Terrain();
  const test::TestStepCostModel model;
  StanceGoal goal;
  goal.stance = StanceAt(2.0);
  FootstepPlannerOptions options;
  options.search.time_limit = 60.0;
  const FootstepPlan plan = PlanFootsteps(terrain, StanceAt(0.0), goal, model, BipedGeometry{}, options);
  ASSERT_TRUE(plan.found) << plan.reason;
  ASSERT_DOUBLE_EQ(plan.statistics.epsilon, 1.0);
  StanceGraph graph(terrain, model, BipedGeometry{}, options, goal);
  double to_go = plan.cost;
  for (int k = -1; k < static_cast<int>(plan.steps.size()); ++k) {
    if (k >= 0) to_go -= plan.steps[k].transition.cost;
    const Stance s = plan.StanceAfter(k);
    // The newer foot is the one that moved last (k = -1: either; check both orders).
    StanceGraph::LatticeFoot left, right;
    ASSERT_TRUE(graph.Snap(s.left, &left));
    ASSERT_TRUE(graph.Snap(s.right, &right));
    const bool left_newer = k >= 0 && plan.steps[k].side == FootSide::kLeft;
    const StanceGraph::Key key = left_newer ? graph.MakeKey(right, left, FootSide::kLeft)
                                            : graph.MakeKey(left, right, FootSide::kRight);
    EXPECT_LE(graph.Heuristic(key), to_go + 1e-9) << "after step " << k;
    if (k + 1 < static_cast<int>(plan.steps.size())) {
      EXPECT_GT(graph.Heuristic(key), 0.5 * to_go) << "after step " << k << ": a useless heuristic";
    }
  }
  EXPECT_NEAR(to_go, 0.0, 1e-9);
}

TEST(StanceGraphTest, FootholdsNeedFlatWalkableGroundUnderTheWholeSole) {
  const TerrainMap terrain = Terrain();
  const test::TestStepCostModel model;
  StanceGoal goal;
  goal.stance = StanceAt(2.0);
  StanceGraph graph(terrain, model, BipedGeometry{}, FootstepPlannerOptions{}, goal);
  StanceGraph::LatticeFoot foot;
  ASSERT_TRUE(graph.Snap(FootPose{1.2, 0.0, 0.0, 0.0}, &foot));
  EXPECT_TRUE(graph.EvaluateFoothold(foot).supported);
  EXPECT_DOUBLE_EQ(graph.EvaluateFoothold(foot).friction, 1.0);
  // Straddling the edge of the step at x = 1.5 (the sole is 0.24 m long).
  ASSERT_TRUE(graph.Snap(FootPose{1.5, 0.0, 0.0, 0.0}, &foot));
  EXPECT_FALSE(graph.EvaluateFoothold(foot).supported);
  // Turned by 90 degrees the sole fits between x = 1.43 and 1.57... still across the edge.
  ASSERT_TRUE(graph.Snap(FootPose{1.5, 0.0, 0.0, M_PI / 2}, &foot));
  EXPECT_FALSE(graph.EvaluateFoothold(foot).supported);
  // On the step, its height; half on the slippery strip, the strip's friction.
  ASSERT_TRUE(graph.Snap(FootPose{1.8, 0.0, 0.0, 0.0}, &foot));
  EXPECT_NEAR(graph.EvaluateFoothold(foot).z, 0.1, 1e-6);
  ASSERT_TRUE(graph.Snap(FootPose{0.55, 0.0, 0.0, 0.0}, &foot));
  EXPECT_FLOAT_EQ(graph.EvaluateFoothold(foot).friction, 0.12f);
  // Off the map.
  EXPECT_FALSE(graph.Snap(FootPose{5.0, 0.0, 0.0, 0.0}, &foot));
}

}  // namespace
}  // namespace cairn::planning
