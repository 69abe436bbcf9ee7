#include <cairn/planning/footstep/plan_footsteps.h>

#include <chrono>
#include <cmath>
#include <limits>
#include <string>
#include <utility>

#include <gtest/gtest.h>

#include <cairn/planning/footstep/stance_graph.h>
#include <cairn/planning/footstep/time_limit_reached.h>

#include "expect_throws.h"
#include "test_step_cost_model.h"

namespace cairn::planning {
namespace {

using test::TestStepCostModel;

// Flat ground of friction `mu` over [x0, x1] x [y0, y1] at 2.5 cm.
TerrainMap FlatGround(double x0, double y0, double x1, double y1, double mu) {
  const double res = 0.025;
  TerrainMap map(Eigen::Vector2d(x0, y0), static_cast<int>(std::lround((x1 - x0) / res)),
                 static_cast<int>(std::lround((y1 - y0) / res)), res);
  for (int r = 0; r < map.rows(); ++r) {
    for (int c = 0; c < map.cols(); ++c) map.SetCell(c, r, 0.0, Eigen::Vector3d::UnitZ(), mu);
  }
  return map;
}

void Paint(TerrainMap* map, double x0, double y0, double x1, double y1, double height, double mu) {
  for (int r = 0; r < map->rows(); ++r) {
    for (int c = 0; c < map->cols(); ++c) {
      const Eigen::Vector2d p = map->CellCenter(c, r);
      if (p.x() >= x0 && p.x() < x1 && p.y() >= y0 && p.y() < y1) {
        map->SetCell(c, r, height, Eigen::Vector3d::UnitZ(), mu);
      }
    }
  }
}

Stance StanceAt(double x, double y = 0.0) {
  Stance s;
  s.left = FootPose{x, y + 0.1, 0.0, 0.0};
  s.right = FootPose{x, y - 0.1, 0.0, 0.0};
  return s;
}

StanceGoal GoalAt(double x, double y = 0.0) {
  StanceGoal goal;
  goal.stance = StanceAt(x, y);
  return goal;
}

FootstepPlannerOptions Options() {
  FootstepPlannerOptions options;
  options.search.time_limit = 30.0;  // generous: tests check the answer, not the speed
  return options;
}

// Checks that consecutive stances are valid steps of `model` and the plan ends at the goal.
void ExpectConsistentPlan(const FootstepPlan& plan, const StanceGoal& goal, const TestStepCostModel& model) {
  ASSERT_TRUE(plan.found) << plan.reason;
  ASSERT_FALSE(plan.steps.empty());
  for (std::size_t k = 0; k < plan.steps.size(); ++k) {
    const PlannedStep& step = plan.steps[k];
    if (k > 0) {
      EXPECT_NE(step.side, plan.steps[k - 1].side) << "feet must alternate";
    }
    EXPECT_TRUE(model.reach().Contains(step.displacement)) << "step " << k;
    EXPECT_TRUE(step.transition.feasible);
    EXPECT_LE(step.transition.rcof, step.mu_allowed + 1e-12);
  }
  const Stance end = plan.StanceAfter(static_cast<int>(plan.steps.size()) - 1);
  EXPECT_LE(std::hypot(end.left.x - goal.stance.left.x, end.left.y - goal.stance.left.y), goal.position_tolerance);
  EXPECT_LE(std::hypot(end.right.x - goal.stance.right.x, end.right.y - goal.stance.right.y),
            goal.position_tolerance);
  double cost = 0.0;
  for (const PlannedStep& step : plan.steps) cost += step.transition.cost;
  EXPECT_NEAR(plan.cost, cost, 1e-9);
}

TEST(PlanFootstepsTest, WalksStraightOnFlatGroundOptimally) {
  const TerrainMap ground = FlatGround(-0.5, -1.0, 2.5, 1.0, 1.0);
  const TestStepCostModel model;
  const StanceGoal goal = GoalAt(1.5);
  const FootstepPlan plan = PlanFootsteps(ground, StanceAt(0.0), goal, model, BipedGeometry{}, Options());
  ExpectConsistentPlan(plan, goal, model);
  EXPECT_DOUBLE_EQ(plan.statistics.epsilon, 1.0);
  EXPECT_GT(plan.statistics.first_plan_seconds, 0.0);
  EXPECT_NEAR(plan.distance, 1.5, 0.15);
  // A foot lands at most 0.38 m ahead of the other, so it advances at most 0.76 m per step: both feet need at
  // least two steps each to cover 1.4 m.
  EXPECT_GE(plan.steps.size(), 4u);
  EXPECT_LE(plan.steps.size(), 7u);
  // Never worse than the admissible bound.
  EXPECT_GE(plan.cost, model.per_metre * 1.5);
}

TEST(PlanFootstepsTest, WalksAroundAWallAndKeepsTheBodyClear) {
  TerrainMap ground = FlatGround(-0.5, -1.5, 2.5, 1.5, 1.0);
  ground.AddObstacle({"wall", Eigen::Vector3d(0.9, 0.0, 1.0), Eigen::Vector3d(0.05, 0.6, 1.0), 0.0});
  const TestStepCostModel model;
  const StanceGoal goal = GoalAt(1.8);
  const BipedGeometry geometry;
  // The first plan of a search inflated by 2 (proving optimality around a wall takes about a million expansions).
  FootstepPlannerOptions options = Options();
  options.search.initial_epsilon = 2.0;
  options.search.final_epsilon = 2.0;
  const FootstepPlan plan = PlanFootsteps(ground, StanceAt(0.0), goal, model, geometry, options);
  ExpectConsistentPlan(plan, goal, model);
  EXPECT_LE(plan.statistics.epsilon, 2.0);
  for (int k = 0; k < static_cast<int>(plan.steps.size()); ++k) {
    const Stance s = plan.StanceAfter(k);
    const Eigen::Vector3d mid(0.5 * (s.left.x + s.right.x), 0.5 * (s.left.y + s.right.y),
                              geometry.body_bottom + geometry.body_half_extents.z());
    EXPECT_FALSE(ground.BoxHitsObstacle(mid, geometry.body_half_extents, 0.5 * (s.left.theta + s.right.theta)))
        << "stance after step " << k;
  }
  EXPECT_GT(plan.distance, 1.8 + 0.2);  // a detour
  EXPECT_GT(plan.statistics.rejected_collision, 0);
}

// Uncertain evidence of an obstacle (occupied voxels with probability 0.6 where a wall would stand): the body
// must keep clear of it at eta_geom = 0.9 (each voxel alone leaves it free with probability 0.4 < 0.9), and may
// walk through it when the planner accepts any evidence (eta_geom = 1e-300).
TEST(PlanFootstepsTest, KeepsTheBodyOutOfUncertainObstaclesByItsFreeProbability) {
  TerrainMap ground = FlatGround(-0.5, -1.5, 2.5, 1.5, 1.0);
  std::vector<TerrainMap::OccupiedVoxel> voxels;
  // 15 cm thick: stance midpoints advance at most 0.38 m per step, less than the wall plus the 0.3 m body.
  for (double x = 0.875; x < 1.0; x += 0.05) {
    for (double y = -0.575; y < 0.6; y += 0.05) {
      for (double z = 0.725; z < 1.3; z += 0.05) voxels.push_back({Eigen::Vector3d(x, y, z), 0.6});
    }
  }
  ground.SetOccupiedVoxels(voxels, 0.05);
  const TestStepCostModel model;
  const StanceGoal goal = GoalAt(1.8);
  const BipedGeometry geometry;
  FootstepPlannerOptions options = Options();
  options.search.initial_epsilon = 2.0;
  options.search.final_epsilon = 2.0;
  // An expansion budget, not the wall clock: the sanitized build is about ten times slower.
  options.search.time_limit = std::numeric_limits<double>::infinity();
  options.search.max_expansions = 5000000;
  const FootstepPlan cautious = PlanFootsteps(ground, StanceAt(0.0), goal, model, geometry, options);
  ExpectConsistentPlan(cautious, goal, model);
  for (int k = 0; k < static_cast<int>(cautious.steps.size()); ++k) {
    const Stance s = cautious.StanceAfter(k);
    const Eigen::Vector3d mid(0.5 * (s.left.x + s.right.x), 0.5 * (s.left.y + s.right.y),
                              geometry.body_bottom + geometry.body_half_extents.z());
    EXPECT_GE(ground.BoxFreeProbability(mid, geometry.body_half_extents, 0.5 * (s.left.theta + s.right.theta)), 0.9)
        << "stance after step " << k;
  }
  EXPECT_GT(cautious.distance, 1.8 + 0.2);  // a detour
  options.min_body_free_probability = 1e-300;  // any evidence is acceptable (0.4^162 > 1e-300): straight through
  const FootstepPlan bold = PlanFootsteps(ground, StanceAt(0.0), goal, model, geometry, options);
  ExpectConsistentPlan(bold, goal, model);
  EXPECT_LT(bold.distance, 1.8 + 0.15);
  options.min_body_free_probability = 0.0;
  CAIRN_EXPECT_THROWS_WITH(PlanFootsteps(ground, StanceAt(0.0), goal, model, geometry, options),
                           std::invalid_argument, "min_body_free_probability must be in (0, 1], got 0");
}

TEST(PlanFootstepsTest, ShortensStepsOnLowFrictionOrWalksAround) {
  // Slippery strip across the way: steps touching it must satisfy 0.05 + 0.5 dx <= 0.12, i.e. dx <= 0.14.
  TerrainMap ground = FlatGround(-0.5, -1.0, 2.5, 1.0, 1.0);
  Paint(&ground, 0.6, -1.0, 1.0, 1.0, 0.0, 0.12);
  const TestStepCostModel model;
  const StanceGoal goal = GoalAt(1.6);
  const FootstepPlan plan = PlanFootsteps(ground, StanceAt(0.0), goal, model, BipedGeometry{}, Options());
  ExpectConsistentPlan(plan, goal, model);
  bool touched_ice = false;
  for (const PlannedStep& step : plan.steps) {
    if (step.mu_allowed < 0.5) {
      touched_ice = true;
      EXPECT_LE(step.displacement.dx, 0.14 + 1e-9);
    }
  }
  EXPECT_TRUE(touched_ice) << "the strip spans the whole map, so the plan must cross it";
  EXPECT_GT(plan.min_friction_margin, -1e-12);
}

// Perceived ground: level, but every cell's height off by up to 4 mm (a fixed pattern). Priced as measured, each
// step climbs a few millimetres; within level_step_tolerance the steps are level ones and the plan costs what it
// costs on flat ground, while its footholds keep the measured heights.
TEST(PlanFootstepsTest, PricesHeightsWithinTheLevelStepToleranceAsLevelSteps) {
  const TerrainMap flat = FlatGround(-0.5, -1.0, 2.5, 1.0, 1.0);
  TerrainMap bumpy = flat;
  for (int r = 0; r < bumpy.rows(); ++r) {
    for (int c = 0; c < bumpy.cols(); ++c) {
      bumpy.SetCell(c, r, 0.001 * ((7 * c + 3 * r) % 5), Eigen::Vector3d::UnitZ(), 1.0);
    }
  }
  const TestStepCostModel model;
  const StanceGoal goal = GoalAt(1.5);
  const FootstepPlan on_flat = PlanFootsteps(flat, StanceAt(0.0), goal, model, BipedGeometry{}, Options());
  const FootstepPlan as_measured = PlanFootsteps(bumpy, StanceAt(0.0), goal, model, BipedGeometry{}, Options());
  FootstepPlannerOptions tolerant = Options();
  tolerant.level_step_tolerance = 0.005;
  const FootstepPlan level = PlanFootsteps(bumpy, StanceAt(0.0), goal, model, BipedGeometry{}, tolerant);
  ExpectConsistentPlan(on_flat, goal, model);
  ExpectConsistentPlan(as_measured, goal, model);
  ExpectConsistentPlan(level, goal, model);
  EXPECT_GT(as_measured.cost, on_flat.cost + 1e-6);
  EXPECT_NEAR(level.cost, on_flat.cost, 1e-9);
  bool measured_height = false;
  for (const PlannedStep& step : level.steps) {
    EXPECT_EQ(step.displacement.dz, 0.0);
    measured_height = measured_height || step.pose.z != 0.0;
  }
  EXPECT_TRUE(measured_height) << "the footholds keep the terrain's heights";
  tolerant.level_step_tolerance = -0.01;
  CAIRN_EXPECT_THROWS_WITH(PlanFootsteps(bumpy, StanceAt(0.0), goal, model, BipedGeometry{}, tolerant),
                           std::invalid_argument, "level_step_tolerance must be in [0, 1] m, got -0.01");
}

TEST(PlanFootstepsTest, ClimbsStepsWithinReachAndPutsFeetOnTreads) {
  TerrainMap ground = FlatGround(-0.5, -1.0, 3.0, 1.0, 1.0);
  Paint(&ground, 1.0, -1.0, 1.4, 1.0, 0.1, 1.0);
  Paint(&ground, 1.4, -1.0, 3.0, 1.0, 0.2, 1.0);
  const TestStepCostModel model;
  StanceGoal goal = GoalAt(2.0);
  goal.stance.left.z = goal.stance.right.z = 0.2;
  const FootstepPlan plan = PlanFootsteps(ground, StanceAt(0.0), goal, model, BipedGeometry{}, Options());
  ExpectConsistentPlan(plan, goal, model);
  for (const PlannedStep& step : plan.steps) {
    // Soles never straddle a riser: every foot stands at one of the three heights.
    const double z = step.pose.z;
    EXPECT_TRUE(std::abs(z) < 1e-6 || std::abs(z - 0.1) < 1e-6 || std::abs(z - 0.2) < 1e-6) << z;
  }
  EXPECT_NEAR(plan.steps.back().pose.z, 0.2, 1e-6);
}

TEST(PlanFootstepsTest, ExplainsWhyThereIsNoPlan) {
  const TestStepCostModel model;
  const FootstepPlannerOptions options = Options();
  {  // A trench wider than any step.
    TerrainMap ground = FlatGround(-0.5, -1.0, 2.5, 1.0, 1.0);
    for (int r = 0; r < ground.rows(); ++r) {
      for (int c = 0; c < ground.cols(); ++c) {
        const double x = ground.CellCenter(c, r).x();
        if (x > 0.6 && x < 1.2) ground.ClearCell(c, r);
      }
    }
    const FootstepPlan plan = PlanFootsteps(ground, StanceAt(0.0), GoalAt(1.8), model, BipedGeometry{}, options);
    EXPECT_FALSE(plan.found);
    EXPECT_NE(plan.reason.find("the goal is unreachable"), std::string::npos) << plan.reason;
  }
  {  // Ice everywhere beyond x = 0.3 that no step can use (a narrow corridor keeps the exhaustive search short).
    TerrainMap ground = FlatGround(-0.3, -0.5, 2.5, 0.5, 1.0);
    Paint(&ground, 0.3, -0.5, 2.5, 0.5, 0.0, 0.04);
    const FootstepPlan plan = PlanFootsteps(ground, StanceAt(0.0), GoalAt(1.8), model, BipedGeometry{}, options);
    EXPECT_FALSE(plan.found);
    EXPECT_NE(plan.reason.find("needs more friction than the terrain offers (a path ignoring friction needs an RCOF of"),
              std::string::npos)
        << plan.reason;
  }
  {  // The start stands in water (friction 0).
    TerrainMap ground = FlatGround(-0.5, -1.0, 2.5, 1.0, 1.0);
    Paint(&ground, -0.5, -1.0, 0.3, 1.0, 0.0, 0.0);
    const FootstepPlan plan = PlanFootsteps(ground, StanceAt(0.0), GoalAt(1.8), model, BipedGeometry{}, options);
    EXPECT_FALSE(plan.found);
    EXPECT_NE(plan.reason.find("start left foot at (0.00, 0.10) is not supported: the ground there is not walkable"),
              std::string::npos)
        << plan.reason;
  }
  {  // The goal is off the map.
    const TerrainMap ground = FlatGround(-0.5, -1.0, 2.5, 1.0, 1.0);
    const FootstepPlan plan = PlanFootsteps(ground, StanceAt(0.0), GoalAt(4.0), model, BipedGeometry{}, options);
    EXPECT_FALSE(plan.found);
    EXPECT_NE(plan.reason.find("goal left foot at (4.00, 0.10) lies outside the terrain map"), std::string::npos)
        << plan.reason;
  }
}

// The search ends at any stance within the goal's tolerances, so a goal foothold that cannot carry a foot (a
// perceived terrain rarely supports the exact goal pose) only stops the plan when nothing within the tolerance can.
TEST(PlanFootstepsTest, AGoalFootholdWithoutSupportIsReplacedByOneWithinTheTolerance) {
  const TestStepCostModel model;
  TerrainMap ground = FlatGround(-0.5, -1.0, 2.5, 1.0, 1.0);
  Paint(&ground, 1.7875, -0.1125, 1.8125, -0.0875, 0.0, 0.0);  // one cell of water under the right goal foot
  const StanceGoal goal = GoalAt(1.8);
  const FootstepPlan plan = PlanFootsteps(ground, StanceAt(0.0), goal, model, BipedGeometry{}, Options());
  ASSERT_TRUE(plan.found) << plan.reason;
  const Stance end = plan.StanceAfter(static_cast<int>(plan.steps.size()) - 1);
  EXPECT_LE(std::hypot(end.right.x - 1.8, end.right.y + 0.1), goal.position_tolerance + 1e-9);
  EXPECT_GT(std::hypot(end.right.x - 1.8, end.right.y + 0.1), 1e-9);  // not the exact goal foothold
  // Water over the whole tolerance disk of the right foot.
  Paint(&ground, 1.6, -0.4, 2.0, 0.0, 0.0, 0.0);
  const FootstepPlan none = PlanFootsteps(ground, StanceAt(0.0), goal, model, BipedGeometry{}, Options());
  EXPECT_FALSE(none.found);
  EXPECT_NE(none.reason.find("goal right foot at (1.80, -0.10) is not supported: the ground there is not walkable "
                             "(friction 0), nor is any foothold within the goal's tolerance (0.1 m, 0.27 rad); move the goal or "
                             "widen its tolerance"),
            std::string::npos)
      << none.reason;
  // At the map's edge, the footholds around the goal that would lie off the lattice are not looked at.
  TerrainMap edge = FlatGround(-0.5, -1.0, 2.5, 1.0, 1.0);
  Paint(&edge, 2.4, -1.0, 2.5, 0.0, 0.0, 0.0);
  const FootstepPlan at_edge = PlanFootsteps(edge, StanceAt(0.0), GoalAt(2.45), model, BipedGeometry{}, Options());
  EXPECT_FALSE(at_edge.found);
  EXPECT_NE(at_edge.reason.find("nor is any foothold within the goal's tolerance"), std::string::npos) << at_edge.reason;
}

TEST(PlanFootstepsTest, ReturnsTheBestPlanSoFarWhenStoppedEarly) {
  const TerrainMap ground = FlatGround(-0.5, -1.5, 3.5, 1.5, 1.0);
  const TestStepCostModel model;
  FootstepPlannerOptions options = Options();
  options.search.initial_epsilon = 3.0;
  options.search.max_expansions = 400;
  const FootstepPlan plan = PlanFootsteps(ground, StanceAt(0.0), GoalAt(2.5), model, BipedGeometry{}, options);
  ASSERT_TRUE(plan.found) << plan.reason;
  EXPECT_GE(plan.statistics.epsilon, 1.0);
  EXPECT_LE(plan.statistics.epsilon, 3.0);
  EXPECT_LE(plan.statistics.expansions, 400);
}

TEST(PlanFootstepsTest, RejectsBadOptions) {
  const TerrainMap ground = FlatGround(0.0, 0.0, 1.0, 1.0, 1.0);
  const TestStepCostModel model;
  FootstepPlannerOptions options = Options();
  options.orientations = 40;
  CAIRN_EXPECT_THROWS_WITH(PlanFootsteps(ground, StanceAt(0.5, 0.5), GoalAt(0.5, 0.5), model, BipedGeometry{}, options),
                           std::invalid_argument, "orientations must be in [1, 32], got 40");
  options = Options();
  options.lattice_resolution = 0.0001;
  CAIRN_EXPECT_THROWS_WITH(PlanFootsteps(ground, StanceAt(0.5, 0.5), GoalAt(0.5, 0.5), model, BipedGeometry{}, options),
                           std::invalid_argument, "at most 4096 per axis");
}

// The time limit covers the heuristic's precomputation too: a terrain whose set-up alone outlasts it (here, any
// terrain: the limit ends before the first lattice row) is a result without a plan, not a call that runs on.
TEST(PlanFootstepsTest, TheTimeLimitCoversTheSetUpBeforeTheSearch) {
  TerrainMap ground = FlatGround(-0.5, -1.5, 3.5, 1.5, 1.0);
  for (int k = 0; k < 200; ++k) {
    TerrainMap::Obstacle box;
    box.name = "pillar";
    box.center = Eigen::Vector3d(0.5 + 0.01 * k, 1.2, 0.5);
    box.half_extents = Eigen::Vector3d(0.004, 0.004, 0.5);
    ground.AddObstacle(box);
  }
  const TestStepCostModel model;
  FootstepPlannerOptions options = Options();
  options.search.time_limit = 1e-300;  // rounds to no time at all on the clock
  const FootstepPlan plan = PlanFootsteps(ground, StanceAt(0.0), GoalAt(2.5), model, BipedGeometry{}, options);
  EXPECT_FALSE(plan.found);
  EXPECT_NE(plan.reason.find("no plan within the time limit of 1e-300 s"), std::string::npos) << plan.reason;
  EXPECT_NE(plan.reason.find("heuristic"), std::string::npos) << plan.reason;
  EXPECT_NE(plan.reason.find("200 obstacles"), std::string::npos) << plan.reason;
  EXPECT_EQ(plan.statistics.expansions, 0);
  // The stance graph alone, with a deadline that has passed.
  const StanceGoal goal = GoalAt(2.5);
  CAIRN_EXPECT_THROWS_WITH(StanceGraph(ground, model, BipedGeometry{}, Options(), goal,
                                       StanceGraph::Clock::now() - std::chrono::seconds(1)),
                           TimeLimitReached, "the time limit ran out while evaluating the footholds");
}

TEST(PlanFootstepsTest, RefusesStancesThatCannotStand) {
  const TerrainMap ground = FlatGround(-0.5, -1.5, 3.5, 1.5, 1.0);
  const TestStepCostModel model;
  Stance crossed = StanceAt(0.0);
  std::swap(crossed.left, crossed.right);
  CAIRN_EXPECT_THROWS_WITH(PlanFootsteps(ground, crossed, GoalAt(2.5), model, BipedGeometry{}, Options()),
                           std::invalid_argument, "the start stance", "is not to the left of the right foot",
                           "crossed");
  Stance together = StanceAt(0.0);
  together.right = together.left;
  StanceGoal goal = GoalAt(2.5);
  goal.stance = together;
  CAIRN_EXPECT_THROWS_WITH(PlanFootsteps(ground, StanceAt(0.0), goal, model, BipedGeometry{}, Options()),
                           std::invalid_argument, "the goal stance", "both feet stand at one point");
  // Facing -x, the left foot is on the -y side.
  Stance turned = StanceAt(0.0);
  turned.left.theta = turned.right.theta = M_PI;
  EXPECT_NE(StanceGeometryProblem(turned), "");
  std::swap(turned.left.y, turned.right.y);
  EXPECT_EQ(StanceGeometryProblem(turned), "");
  FootstepPlannerOptions options = Options();
  options.search.time_limit = std::nan("");
  CAIRN_EXPECT_THROWS_WITH(PlanFootsteps(ground, StanceAt(0.0), GoalAt(2.5), model, BipedGeometry{}, options),
                           std::invalid_argument, "time_limit must be > 0 seconds, got nan");
}

}  // namespace
}  // namespace cairn::planning
