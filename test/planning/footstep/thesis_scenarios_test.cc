// The thesis' ice-patch experiments (2.4.2, Fig. 2.7, Table 2.1) with the project's humanoid and its default
// transition oracle (objective E_COM + heat). The walking model's constants are physical and documented in
// data/robots; nothing here is tuned to a scenario.

#include <algorithm>
#include <cstdio>
#include <functional>
#include <string>

#include <gtest/gtest.h>

#include <cairn/planning/footstep/plan_footsteps.h>
#include <cairn/planning/footstep/stance_graph.h>
#include <cairn/planning/scenarios/footstep_scenario.h>

#include "../support/shared_oracle.h"
#include "test_paths.h"

namespace cairn::planning {
namespace {

const std::string kScenarios = std::string(CAIRN_SOURCE_DIR) + "/examples/scenarios/";

BipedGeometry GeometryOf(const WalkingModel& model) {
  BipedGeometry geometry;
  geometry.foot_length = model.foot_length();
  geometry.foot_width = model.foot_width();
  geometry.body_half_extents = model.body_half_extents();
  geometry.body_bottom = model.body_box_bottom();
  return geometry;
}

// Plans a scenario to optimality (no time limit, so the answer does not depend on the machine), after letting
// `modify` change its terrain.
FootstepPlan PlanScenario(const std::string& name, const std::function<void(TerrainMap*)>& modify = nullptr) {
  const FootstepScenario scenario = FootstepScenario::Load(kScenarios + name + ".yaml");
  TerrainMap terrain = scenario.BuildTerrain();
  if (modify) modify(&terrain);
  FootstepPlannerOptions options = scenario.planner();
  options.search.time_limit = std::numeric_limits<double>::infinity();
  const auto oracle = test::SharedOracle(WalkingObjective::kComWorkPlusHeat);
  FootstepPlan plan = PlanFootsteps(terrain, scenario.start(), scenario.goal(), *oracle,
                                    GeometryOf(*test::SharedWalkingModel()), options);
  std::printf("%-16s found %d  steps %2zu  cost %7.1f J  duration %5.1f s  distance %4.2f m  max RCOF %.3f  "
              "expansions %lld  %.0f ms\n",
              name.c_str(), plan.found, plan.steps.size(), plan.cost, plan.duration, plan.distance, plan.max_rcof,
              static_cast<long long>(plan.statistics.expansions), 1e3 * plan.statistics.plan_seconds);
  return plan;
}

// Steps that touch ice (any of their three feet): their friction limit is the ice's.
bool TouchesIce(const PlannedStep& step) { return step.mu_allowed < 0.5; }

double MeanDuration(const FootstepPlan& plan, bool on_ice) {
  double sum = 0.0;
  int n = 0;
  for (const PlannedStep& step : plan.steps) {
    if (TouchesIce(step) == on_ice) {
      sum += step.transition.duration;
      ++n;
    }
  }
  return n ? sum / n : 0.0;
}

// Removes the ice (friction 0: not walkable), forcing a detour.
void ForbidIce(TerrainMap* terrain) {
  for (int r = 0; r < terrain->rows(); ++r) {
    for (int c = 0; c < terrain->cols(); ++c) {
      if (terrain->walkable(c, r) && terrain->friction(c, r) < 0.5) {
        terrain->SetCell(c, r, terrain->height(c, r), terrain->normal(c, r), 0.0);
      }
    }
  }
}

// Walls from 0.1 m beside the narrow patch (|y| > 0.35, x in [0.4, 2.6]) to the map's edge: the corridor between
// them is wide enough for the body (0.54 m) but not for feet beside the ice, forcing a crossing.
void ForbidDetour(TerrainMap* terrain) {
  terrain->AddObstacle({"left wall", Eigen::Vector3d(1.5, 1.175, 1.0), Eigen::Vector3d(1.1, 0.825, 1.0), 0.0});
  terrain->AddObstacle({"right wall", Eigen::Vector3d(1.5, -1.175, 1.0), Eigen::Vector3d(1.1, 0.825, 1.0), 0.0});
}

TEST(ThesisScenariosTest, NarrowIceAtPoint12IsCrossedSlowly) {
  const FootstepPlan plan = PlanScenario("ice_narrow_012");
  ASSERT_TRUE(plan.found) << plan.reason;
  EXPECT_TRUE(std::any_of(plan.steps.begin(), plan.steps.end(), TouchesIce)) << "expected to cross the ice";
  EXPECT_GT(MeanDuration(plan, true), MeanDuration(plan, false)) << "steps on ice should be slower";
  EXPECT_LE(plan.max_rcof, 1.0);
  for (const PlannedStep& step : plan.steps) EXPECT_LE(step.transition.rcof, step.mu_allowed + 1e-9);
  // The heuristic, built from the oracle's step and stride bounds, never overestimates along the optimal plan.
  {
    const FootstepScenario scenario = FootstepScenario::Load(kScenarios + "ice_narrow_012.yaml");
    const TerrainMap terrain = scenario.BuildTerrain();
    StanceGraph graph(terrain, *test::SharedOracle(WalkingObjective::kComWorkPlusHeat),
                      GeometryOf(*test::SharedWalkingModel()), scenario.planner(), scenario.goal());
    double to_go = plan.cost;
    for (int k = 0; k < static_cast<int>(plan.steps.size()); ++k) {
      to_go -= plan.steps[k].transition.cost;
      const Stance s = plan.StanceAfter(k);
      StanceGraph::LatticeFoot left, right;
      ASSERT_TRUE(graph.Snap(s.left, &left) && graph.Snap(s.right, &right));
      const StanceGraph::Key key = plan.steps[k].side == FootSide::kLeft ? graph.MakeKey(right, left, FootSide::kLeft)
                                                                         : graph.MakeKey(left, right, FootSide::kRight);
      EXPECT_LE(graph.Heuristic(key), to_go + 1e-6) << "after step " << k;
    }
  }
  const FootstepPlan detour = PlanScenario("ice_narrow_012", ForbidIce);
  ASSERT_TRUE(detour.found) << detour.reason;
  EXPECT_GT(detour.cost, plan.cost) << "the forced detour must cost more";
}

TEST(ThesisScenariosTest, NarrowIceAtPoint06IsWalkedAround) {
  const FootstepPlan plan = PlanScenario("ice_narrow_006");
  ASSERT_TRUE(plan.found) << plan.reason;
  EXPECT_FALSE(std::any_of(plan.steps.begin(), plan.steps.end(), TouchesIce)) << "expected a detour";
  EXPECT_GT(plan.distance, 3.0);
  const FootstepPlan crossing = PlanScenario("ice_narrow_006", ForbidDetour);
  ASSERT_TRUE(crossing.found) << crossing.reason;
  EXPECT_TRUE(std::any_of(crossing.steps.begin(), crossing.steps.end(), TouchesIce));
  EXPECT_GT(crossing.cost, plan.cost) << "the forced crossing must cost more";
}

TEST(ThesisScenariosTest, WideIceAtPoint06IsCrossedSlowlyRatherThanAvoided) {
  const FootstepPlan plan = PlanScenario("ice_wide_006");
  ASSERT_TRUE(plan.found) << plan.reason;
  EXPECT_TRUE(std::any_of(plan.steps.begin(), plan.steps.end(), TouchesIce)) << "expected to cross the ice";
  EXPECT_GT(MeanDuration(plan, true), 1.3 * MeanDuration(plan, false)) << "steps on ice should be much slower";
  const FootstepPlan detour = PlanScenario("ice_wide_006", ForbidIce);
  ASSERT_TRUE(detour.found) << detour.reason;
  EXPECT_GT(detour.cost, plan.cost) << "the forced detour must cost more";
}

}  // namespace
}  // namespace cairn::planning
