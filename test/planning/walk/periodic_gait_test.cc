// Periodic gaits: the plan repeats one step exactly (recomputed from the poses, not from the code's own formula),
// ends with the feet side by side, carries the analytic model's prediction; the ground is a floor or a staircase
// whose treads lie under the footholds, and a staircase no ground can hold is refused.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include <cairn/planning/locomotion/step_evaluator.h>
#include <cairn/planning/walk/periodic_gait.h>

#include "../support/shared_oracle.h"
#include "expect_throws.h"

namespace cairn::planning {
namespace {

PeriodicGait Gait(double dx, double dy, double dz, double dtheta) {
  PeriodicGait gait;
  gait.displacement = {dx, dy, dz, dtheta};
  gait.parameters = {0.4, 1.0, 0.7};
  return gait;
}

// The pose of `foot` in the frame of `support`, mirrored for a right foot as StepDisplacement reads it.
StepDisplacement Relative(const FootPose& support, const FootPose& foot, FootSide side) {
  const double sigma = side == FootSide::kLeft ? 1.0 : -1.0;
  const double ex = foot.x - support.x, ey = foot.y - support.y;
  const double c = std::cos(support.theta), s = std::sin(support.theta);
  return {c * ex + s * ey, sigma * (-s * ex + c * ey), foot.z - support.z, sigma * (foot.theta - support.theta)};
}

void ExpectDisplacement(const StepDisplacement& expected, const StepDisplacement& actual, const std::string& what) {
  SCOPED_TRACE(what);
  EXPECT_NEAR(actual.dx, expected.dx, 1e-12);
  EXPECT_NEAR(actual.dy, expected.dy, 1e-12);
  EXPECT_NEAR(actual.dz, expected.dz, 1e-12);
  EXPECT_NEAR(actual.dtheta, expected.dtheta, 1e-12);
}

TEST(PeriodicGaitTest, EveryStepIsTheSameStepMirroredAndTheLastClosesTheStance) {
  const WalkingModel& model = *test::SharedWalkingModel();
  const PeriodicGait gait = Gait(0.2, 0.22, 0.0, 0.2);
  const FootstepPlan plan = PeriodicGaitPlan(gait, model, WalkingObjective::kComWorkPlusHeat, 0.8);
  ASSERT_TRUE(plan.found);
  ASSERT_EQ(plan.steps.size(), 7u);
  EXPECT_EQ(plan.first_side, FootSide::kRight);
  ExpectDisplacement(gait.displacement, Relative(plan.start.right, plan.start.left, FootSide::kLeft), "start");
  StepEvaluator evaluator(model);
  const StepEvaluation expected = evaluator.Evaluate(gait.displacement, gait.parameters);
  for (int k = 0; k < 7; ++k) {
    const PlannedStep& step = plan.steps[static_cast<std::size_t>(k)];
    EXPECT_EQ(step.side, k % 2 == 0 ? FootSide::kRight : FootSide::kLeft);
    const Stance before = plan.StanceAfter(k - 1);
    const FootPose& support = step.side == FootSide::kLeft ? before.right : before.left;
    const StepDisplacement wanted = k < 6 ? gait.displacement : StepDisplacement{0.0, 0.22, 0.0, 0.0};
    ExpectDisplacement(wanted, Relative(support, step.pose, step.side), "step " + std::to_string(k + 1));
    ExpectDisplacement(wanted, step.displacement, "recorded displacement of step " + std::to_string(k + 1));
    EXPECT_EQ(step.mu_allowed, 0.8);
    EXPECT_EQ(step.transition.parameters.t_sw, 1.0);
    EXPECT_DOUBLE_EQ(step.transition.duration, 1.4);
    if (k < 6) {
      EXPECT_EQ(step.transition.com_work, expected.com_work);
      EXPECT_EQ(step.transition.rcof, expected.rcof);
      EXPECT_EQ(step.transition.feasible, expected.feasible);
    }
  }
  // The last stance stands side by side and parallel.
  const Stance end = plan.StanceAfter(6);
  EXPECT_NEAR(end.left.theta, end.right.theta, 1e-12);
  EXPECT_NEAR(Relative(end.right, end.left, FootSide::kLeft).dx, 0.0, 1e-12);
  EXPECT_NEAR(plan.duration, 7 * 1.4, 1e-9);
}

TEST(PeriodicGaitTest, RejectsGaitsOutsideTheModel) {
  const WalkingModel& model = *test::SharedWalkingModel();
  PeriodicGait gait = Gait(0.2, 0.2, 0.0, 0.0);
  gait.num_steps = 0;
  CAIRN_EXPECT_THROWS_WITH(PeriodicGaitPlan(gait, model, WalkingObjective::kComWork, 1.0), std::invalid_argument,
                           "num_steps 0", "[1, 100]");
  CAIRN_EXPECT_THROWS_WITH(PeriodicGaitPlan(Gait(0.9, 0.2, 0.0, 0.0), model, WalkingObjective::kComWork, 1.0),
                           std::invalid_argument, "dx 0.9 m", "reach");
  gait = Gait(0.2, 0.2, 0.0, 0.0);
  gait.parameters.t_sw = 0.1;
  CAIRN_EXPECT_THROWS_WITH(PeriodicGaitPlan(gait, model, WalkingObjective::kComWork, 1.0), std::invalid_argument,
                           "t_sw 0.1 s");
  CAIRN_EXPECT_THROWS_WITH(PeriodicGaitPlan(Gait(0.2, 0.2, 0.0, 0.0), model, WalkingObjective::kComWork, 0.0),
                           std::invalid_argument, "mu_allowed 0");
}

TEST(PeriodicGaitTest, LevelGaitsStandOnOneFloor) {
  const WalkingModel& model = *test::SharedWalkingModel();
  const FootstepPlan plan = PeriodicGaitPlan(Gait(0.3, 0.2, 0.0, 0.0), model, WalkingObjective::kComWork, 1.0);
  const auto boxes = PeriodicGaitTerrain(plan, 0.24, 0.14, 0.9);
  ASSERT_EQ(boxes.size(), 1u);
  const multibody::TerrainBox& floor = boxes[0];
  EXPECT_EQ(floor.friction, 0.9);
  EXPECT_NEAR(floor.X_WB.translation().z() + 0.5 * floor.size.z(), 0.0, 1e-12);
  for (const PlannedStep& step : plan.steps) {
    EXPECT_LT(std::abs(step.pose.x - floor.X_WB.translation().x()), 0.5 * floor.size.x() - 0.9);
    EXPECT_LT(std::abs(step.pose.y - floor.X_WB.translation().y()), 0.5 * floor.size.y() - 0.9);
  }
}

TEST(PeriodicGaitTest, StairsGetATreadUnderEveryFootholdOrAreRefused) {
  const WalkingModel& model = *test::SharedWalkingModel();
  const FootstepPlan plan = PeriodicGaitPlan(Gait(0.3, 0.2, 0.1, 0.0), model, WalkingObjective::kComWork, 1.0);
  const auto treads = PeriodicGaitTerrain(plan, 0.24, 0.14, 1.0, 0.01);
  ASSERT_EQ(treads.size(), 2 + plan.steps.size());
  for (std::size_t k = 0; k < plan.steps.size(); ++k) {
    const multibody::TerrainBox& tread = treads[k + 2];
    const FootPose& foot = plan.steps[k].pose;
    EXPECT_NEAR(tread.X_WB.translation().z() + 0.5 * tread.size.z(), foot.z, 1e-12);
    EXPECT_NEAR(tread.X_WB.translation().x(), foot.x, 1e-12);
    EXPECT_NEAR(tread.size.x(), 0.26, 1e-12);
    EXPECT_NEAR(tread.size.y(), 0.16, 1e-12);
  }
  // The closing foot's tread lies 0.3 m ahead of its last one, at another height: they stand apart.
  EXPECT_NEAR(plan.steps.back().pose.z, plan.steps[5].pose.z, 1e-12);

  // Short steps up: the same foot's treads overlap at different heights.
  const FootstepPlan steep = PeriodicGaitPlan(Gait(0.15, 0.2, 0.1, 0.0), model, WalkingObjective::kComWork, 1.0);
  CAIRN_EXPECT_THROWS_WITH(PeriodicGaitTerrain(steep, 0.24, 0.14, 1.0), std::invalid_argument, "overlap",
                           "no staircase holds both");
  CAIRN_EXPECT_THROWS_WITH(PeriodicGaitTerrain(plan, 0.24, 0.14, 1.0, 0.5), std::invalid_argument, "margin 0.5");
  CAIRN_EXPECT_THROWS_WITH(PeriodicGaitTerrain(plan, 0.0, 0.14, 1.0), std::invalid_argument, "finite sides");
  CAIRN_EXPECT_THROWS_WITH(PeriodicGaitTerrain(FootstepPlan(), 0.24, 0.14, 1.0), std::invalid_argument, "no steps");
}

}  // namespace
}  // namespace cairn::planning
