// Thesis 2.5.2 (Figs. 2.14-2.15): footsteps planned with the crouched body box, then the whole body bends under a
// high bar; a low obstacle forces a footstep detour. Scenario files: examples/scenarios/high_bar*.yaml.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include <gtest/gtest.h>

#include <cairn/multibody/data.h>
#include <cairn/multibody/kinematics.h>
#include <cairn/planning/footstep/biped_geometry.h>
#include <cairn/planning/footstep/plan_footsteps.h>
#include <cairn/planning/scenarios/footstep_scenario.h>
#include <cairn/planning/trajectory/environment_from_obstacles.h>
#include <cairn/planning/trajectory/optimize_whole_body_trajectory.h>

#include "../support/shared_oracle.h"
#include "test_robot.h"
#include "test_paths.h"

namespace cairn::planning {
namespace {

const std::string kScenarios = std::string(CAIRN_SOURCE_DIR) + "/examples/scenarios/";

struct Solved {
  FootstepScenario scenario;
  FootstepPlan plan;
  WholeBodyTrajectory trajectory;
};

FootstepPlan PlanOnly(const FootstepScenario& scenario) {
  FootstepPlannerOptions options = scenario.planner();
  options.search.time_limit = std::numeric_limits<double>::infinity();  // deterministic: an expansion budget
  options.search.max_expansions = 200000;
  const WalkingModel& walking = *test::SharedWalkingModel();
  BipedGeometry geometry;
  geometry.foot_length = walking.foot_length();
  geometry.foot_width = walking.foot_width();
  geometry.body_half_extents = walking.body_half_extents();
  geometry.body_bottom = walking.body_box_bottom();
  const auto oracle = test::SharedOracle(WalkingObjective::kComWorkPlusHeat);
  return PlanFootsteps(scenario.BuildTerrain(), scenario.start(), scenario.goal(), *oracle, geometry, options);
}

Solved PlanAndOptimize(const std::string& name) {
  FootstepScenario scenario = FootstepScenario::Load(kScenarios + name + ".yaml");
  FootstepPlan plan = PlanOnly(scenario);
  WholeBodyTrajectory trajectory;
  if (plan.found) {
    trajectory = OptimizeWholeBodyTrajectory(test::Humanoid(), plan, EnvironmentFromObstacles(scenario.obstacles()));
  }
  std::printf("%s: %zu steps, whole body %s in %d iterations (%d windows), %.2f s: %s\n", name.c_str(),
              plan.steps.size(), trajectory.report.status.c_str(), trajectory.report.iterations,
              trajectory.report.windows, trajectory.report.seconds, trajectory.report.message.c_str());
  return {std::move(scenario), std::move(plan), std::move(trajectory)};
}

double MeanKnee(const WholeBodyWaypoint& w) {
  const auto model = test::Humanoid();
  return 0.5 * (w.q(model->joint(model->GetJointIndex("l_knee")).idx_q) +
                w.q(model->joint(model->GetJointIndex("r_knee")).idx_q));
}

double HeadTop(const WholeBodyWaypoint& w) {
  const auto model = test::Humanoid();
  multibody::Data data(*model);
  multibody::ForwardKinematics(*model, data, w.q);
  // The head sphere: radius 0.1 m, centred 0.06 m above the head frame.
  return (data.X_world[static_cast<std::size_t>(model->GetBodyIndex("head"))] * Eigen::Vector3d(0.0, 0.0, 0.06)).z() +
         0.1;
}

// The robot keeps d_safe from the bar at every waypoint, crouches well below its standing height near the bar, and
// stands straighter where the bar is far. Not asserted: clearance along the motion between waypoints. With one
// collision sample per segment the head can pass the 10 cm bar between two knots (the samples' clearance is
// printed); with more samples the solve did not converge within the iteration budget.
void ExpectBendsUnderTheBarOnly(const Solved& s) {
  ASSERT_TRUE(s.trajectory.found) << s.trajectory.report.message;
  const TrajectoryOptimizerOptions options;
  const double bar_x = 0.75, bar_bottom = 1.30;
  double lowest_head = std::numeric_limits<double>::infinity();
  double knee_near = 0.0, knee_far = 0.0;
  int near = 0, far = 0;
  for (const WholeBodyWaypoint& w : s.trajectory.waypoints) {
    SCOPED_TRACE(w.label);
    EXPECT_GE(w.min_clearance, options.d_safe - 0.005);
    lowest_head = std::min(lowest_head, HeadTop(w));
    if (w.single_support) continue;  // the swing knee bends anyway
    const double dx = std::abs(w.q(0) - bar_x);
    if (dx < 0.4) {
      knee_near += MeanKnee(w);
      ++near;
    } else if (dx > 0.6) {
      knee_far += MeanKnee(w);
      ++far;
    }
  }
  std::printf("lowest head top %.3f m (bar underside %.2f m); clearance at the samples %.3f m (%s)\n", lowest_head,
              bar_bottom, s.trajectory.report.min_sample_clearance, s.trajectory.report.min_sample_pair.c_str());
  // Standing, the head is above the bar's underside; near the bar the robot crouched by more than 10 cm.
  EXPECT_GT(HeadTop(s.trajectory.waypoints.front()), bar_bottom + 0.1);
  EXPECT_LT(lowest_head, HeadTop(s.trajectory.waypoints.front()) - 0.1);
  ASSERT_GT(near, 0);
  ASSERT_GT(far, 0);
  // Torque minimisation straightens the knees where nothing forces them to bend (thesis Fig. 2.14).
  EXPECT_LT(knee_far / far, knee_near / near - 0.1) << "near " << knee_near / near << ", far " << knee_far / far;
}

TEST(ThesisObstaclesTest, HighBarFootstepsGoStraightAndTheBodyBendsUnderTheBar) {
  const Solved s = PlanAndOptimize("high_bar");
  ASSERT_TRUE(s.plan.found) << s.plan.reason;
  for (const PlannedStep& step : s.plan.steps) EXPECT_LT(std::abs(std::abs(step.pose.y) - 0.1), 0.06);
  ExpectBendsUnderTheBarOnly(s);
}

// The detour itself (16 steps) is asserted at the footstep level only: its whole-body solve does not converge.
// Measured 2026-12-02: whole plan, 500 iterations (the limit) with every constraint row within 1e-6, so it is
// stationarity, not feasibility, that fails; in windows of 2 stances some windows stop at their 500-iteration
// limit (2995 iterations over 16 windows), also with tolerance 1e-4 (3002), the worst rows then at stance 4
// mid-swing, beside the low box (1e-5 on the unit quaternion). Not yet confirmed: that the box-box distances
// between the swing leg and the low box (whose witness points jump between faces) are what keeps the dual
// infeasibility from falling.
TEST(ThesisObstaclesTest, ALowObstacleForcesAFootstepDetour) {
  const FootstepScenario scenario = FootstepScenario::Load(kScenarios + "high_bar_low_obstacle.yaml");
  const FootstepPlan plan = PlanOnly(scenario);
  ASSERT_TRUE(plan.found) << plan.reason;
  double widest = 0.0;
  for (const PlannedStep& step : plan.steps) widest = std::max(widest, std::abs(step.pose.y));
  EXPECT_GT(widest, 0.3);
}

}  // namespace
}  // namespace cairn::planning
