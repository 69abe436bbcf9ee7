#include <cairn/planning/footstep/footstep_replanner.h>

#include <cmath>
#include <limits>
#include <string>
#include <utility>

#include <gtest/gtest.h>

#include <cairn/planning/footstep/plan_footsteps.h>
#include <cairn/planning/scenarios/footstep_scenario.h>

#include "../support/shared_oracle.h"
#include "expect_throws.h"
#include "test_paths.h"

namespace cairn::planning {
namespace {

BipedGeometry HumanoidGeometry() {
  const auto model = test::SharedWalkingModel();
  BipedGeometry geometry;
  geometry.foot_length = model->foot_length();
  geometry.foot_width = model->foot_width();
  geometry.body_half_extents = model->body_half_extents();
  geometry.body_bottom = model->body_box_bottom();
  return geometry;
}

void ExpectSamePlan(const FootstepPlan& a, const FootstepPlan& b) {
  ASSERT_EQ(a.found, b.found) << a.reason << " | " << b.reason;
  EXPECT_EQ(a.reason, b.reason);
  EXPECT_EQ(a.cost, b.cost);
  EXPECT_EQ(a.statistics.epsilon, b.statistics.epsilon);
  EXPECT_EQ(a.statistics.expansions, b.statistics.expansions);
  EXPECT_EQ(a.statistics.rejected_support, b.statistics.rejected_support);
  ASSERT_EQ(a.steps.size(), b.steps.size());
  for (std::size_t k = 0; k < a.steps.size(); ++k) {
    EXPECT_EQ(a.steps[k].pose.x, b.steps[k].pose.x);
    EXPECT_EQ(a.steps[k].pose.y, b.steps[k].pose.y);
    EXPECT_EQ(a.steps[k].pose.theta, b.steps[k].pose.theta);
    EXPECT_EQ(a.steps[k].transition.cost, b.steps[k].transition.cost);
  }
}

struct Loaded {
  FootstepScenario scenario;
  TerrainMap terrain;
  FootstepPlannerOptions options;
};

Loaded Load(const std::string& name) {
  FootstepScenario scenario =
      FootstepScenario::Load(std::string(CAIRN_SOURCE_DIR) + "/examples/scenarios/" + name + ".yaml");
  TerrainMap terrain = scenario.BuildTerrain();
  FootstepPlannerOptions options = scenario.planner();
  options.search.time_limit = std::numeric_limits<double>::infinity();
  return Loaded{std::move(scenario), std::move(terrain), options};
}

// As the robot walks: every replan equals PlanFootsteps from the same start, and the later ones reuse the
// precomputation.
TEST(FootstepReplannerTest, ReplansAsPlanFootstepsWouldAfterEachStep) {
  const Loaded s = Load("ice_wide_006");
  const auto oracle = test::SharedOracle(WalkingObjective::kComWorkPlusHeat);
  FootstepReplanner replanner(s.terrain, s.scenario.goal(), oracle, HumanoidGeometry(), s.options);
  EXPECT_FALSE(replanner.prepared());
  const FootstepPlan first = replanner.Plan(s.scenario.start());
  EXPECT_TRUE(replanner.prepared());
  ExpectSamePlan(first, PlanFootsteps(s.terrain, s.scenario.start(), s.scenario.goal(), *oracle, HumanoidGeometry(),
                                      s.options));
  ASSERT_TRUE(first.found);
  for (int k : {0, 1, 5}) {
    const Stance start = first.StanceAfter(k);
    const FootstepPlan replan = replanner.Plan(start);
    ExpectSamePlan(replan, PlanFootsteps(s.terrain, start, s.scenario.goal(), *oracle, HumanoidGeometry(), s.options));
    ASSERT_TRUE(replan.found);
    // Bellman: the rest of an optimal plan is optimal.
    double rest = 0.0;
    for (std::size_t j = k + 1; j < first.steps.size(); ++j) rest += first.steps[j].transition.cost;
    EXPECT_NEAR(replan.cost, rest, 1e-6) << "after step " << k;
  }
}

// A failed search is explained with friction ignored; the next plan must see the friction again.
TEST(FootstepReplannerTest, AFailureDoesNotLeakIntoTheNextPlan) {
  Loaded s = Load("flat");
  // A moat 0.6 m wide (more than a step) around the origin: a start inside it cannot reach the goal.
  for (int r = 0; r < s.terrain.rows(); ++r) {
    for (int c = 0; c < s.terrain.cols(); ++c) {
      const double radius = s.terrain.CellCenter(c, r).norm();
      if (radius > 0.5 && radius < 1.1) s.terrain.ClearCell(c, r);
    }
  }
  const auto oracle = test::SharedOracle(WalkingObjective::kComWorkPlusHeat);
  FootstepReplanner replanner(s.terrain, s.scenario.goal(), oracle, HumanoidGeometry(), s.options);
  const FootstepPlan trapped = replanner.Plan(s.scenario.start());
  EXPECT_FALSE(trapped.found);
  EXPECT_NE(trapped.reason.find("unreachable"), std::string::npos) << trapped.reason;
  Stance outside = s.scenario.start();
  outside.left.x = outside.right.x = 1.6;
  ExpectSamePlan(replanner.Plan(outside),
                 PlanFootsteps(s.terrain, outside, s.scenario.goal(), *oracle, HumanoidGeometry(), s.options));
}

// A new patch of ice ahead only raises step costs: the precomputed heuristic is kept and the replan is still
// optimal (the cost PlanFootsteps finds on the new terrain). More friction somewhere discards it.
TEST(FootstepReplannerTest, KeepsTheHeuristicWhenTheTerrainOnlyGotWorse) {
  const Loaded s = Load("flat");
  const auto oracle = test::SharedOracle(WalkingObjective::kComWorkPlusHeat);
  FootstepReplanner replanner(s.terrain, s.scenario.goal(), oracle, HumanoidGeometry(), s.options);
  const FootstepPlan first = replanner.Plan(s.scenario.start());
  ASSERT_TRUE(first.found && first.steps.size() > 6);
  TerrainMap icy = s.terrain;
  const FootPose& p = first.steps[4].pose;
  for (int r = 0; r < icy.rows(); ++r) {
    for (int c = 0; c < icy.cols(); ++c) {
      const Eigen::Vector2d q = icy.CellCenter(c, r);
      if (std::abs(q.x() - p.x) < 0.15 && std::abs(q.y() - p.y) < 0.15) {
        icy.SetCell(c, r, icy.height(c, r), icy.normal(c, r), 0.06);
      }
    }
  }
  EXPECT_TRUE(replanner.UpdateTerrain(icy));
  EXPECT_TRUE(replanner.prepared());
  const FootstepPlan replan = replanner.Plan(s.scenario.start());
  const FootstepPlan direct = PlanFootsteps(icy, s.scenario.start(), s.scenario.goal(), *oracle, HumanoidGeometry(),
                                            s.options);
  ASSERT_TRUE(replan.found && direct.found);
  EXPECT_EQ(replan.statistics.epsilon, 1.0);
  EXPECT_NEAR(replan.cost, direct.cost, 1e-6);
  EXPECT_GT(replan.cost, first.cost) << "the ice lies on the old plan's way";

  TerrainMap grippy = icy;
  grippy.SetCell(0, 0, grippy.height(0, 0), grippy.normal(0, 0), 2.0);
  EXPECT_FALSE(replanner.UpdateTerrain(grippy));
  EXPECT_FALSE(replanner.prepared());
  EXPECT_NEAR(replanner.Plan(s.scenario.start()).cost,
              PlanFootsteps(grippy, s.scenario.start(), s.scenario.goal(), *oracle, HumanoidGeometry(), s.options).cost,
              1e-6);
  CAIRN_EXPECT_THROWS_WITH(replanner.UpdateTerrain(TerrainMap(s.terrain.origin(), 10, 10, s.terrain.resolution())),
                           std::invalid_argument, "grid (10 x 10 cells");
}

TEST(FootstepReplannerTest, RejectsBadInput) {
  const Loaded s = Load("flat");
  CAIRN_EXPECT_THROWS_WITH(FootstepReplanner(s.terrain, s.scenario.goal(), nullptr, HumanoidGeometry(), s.options),
                           std::invalid_argument, "cost model is null");
  StanceGoal crossed = s.scenario.goal();
  std::swap(crossed.stance.left, crossed.stance.right);
  CAIRN_EXPECT_THROWS_WITH(FootstepReplanner(s.terrain, crossed, test::SharedOracle(WalkingObjective::kComWorkPlusHeat),
                                             HumanoidGeometry(), s.options),
                           std::invalid_argument, "goal stance");
}

}  // namespace
}  // namespace cairn::planning
