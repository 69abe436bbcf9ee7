// Problem (2.9) on a straight plan: gradients of the whole program, and the solution's constraints.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <cairn/multibody/center_of_mass.h>
#include <cairn/multibody/data.h>
#include <cairn/multibody/kinematics.h>
#include <cairn/optimization/check_gradients.h>
#include <cairn/planning/trajectory/frame_pose_error.h>
#include <cairn/planning/trajectory/optimize_whole_body_trajectory.h>
#include <cairn/planning/trajectory/trajectory_problem.h>
#include <cairn/planning/trajectory/waypoint_spec.h>

#include "expect_throws.h"
#include "test_robot.h"

namespace cairn::planning {
namespace {

TEST(WaypointSpecTest, AlternatesDoubleAndSingleSupportWithThePersistingFootAsSupport) {
  const auto specs = MakeWaypointSpecs(test::StraightPlan(3, 0.2), TrajectoryOptimizerOptions());
  ASSERT_EQ(specs.size(), 7u);
  EXPECT_EQ(specs[0].label, "stance 0 start");
  EXPECT_EQ(specs[1].label, "stance 0 mid-swing");
  EXPECT_EQ(specs[0].contacts.size(), 2u);
  ASSERT_EQ(specs[1].contacts.size(), 1u);
  EXPECT_EQ(specs[1].contacts[0].frame, "l_sole");  // the right foot swings first
  EXPECT_EQ(specs[0].supports[0].frame, "l_sole");
  EXPECT_NEAR(specs[1].time, 0.5, 1e-12);
  EXPECT_NEAR(specs[2].time, 0.8, 1e-12);
  EXPECT_EQ(specs[6].supports.size(), 2u);            // the final stance: both feet, half the weight each
  EXPECT_EQ(specs[6].polygon_vertices.size(), 4u);    // hull of two aligned rectangles
  FootstepPlan missing;
  CAIRN_EXPECT_THROWS_WITH(MakeWaypointSpecs(missing, TrajectoryOptimizerOptions()), std::invalid_argument,
                           "not found");
  FootstepPlan untimed = test::StraightPlan(1, 0.2);
  untimed.steps[0].transition.parameters.t_sw = 0.0;
  CAIRN_EXPECT_THROWS_WITH(MakeWaypointSpecs(untimed, TrajectoryOptimizerOptions()), std::invalid_argument,
                           "step 1 has t_ds = 0.2 s and t_sw = 0 s");
}

// A 10-degree slope rising along +x (thesis Fig. 2.8), 2 m x 2 m around the origin.
TerrainMap Slope(double degrees) {
  const double a = degrees * M_PI / 180.0;
  TerrainMap terrain(Eigen::Vector2d(-1.0, -1.0), 40, 40, 0.05);
  for (int row = 0; row < terrain.rows(); ++row) {
    for (int col = 0; col < terrain.cols(); ++col) {
      terrain.SetCell(col, row, terrain.CellCenter(col, row).x() * std::tan(a),
                      Eigen::Vector3d(-std::sin(a), 0.0, std::cos(a)), 1.0);
    }
  }
  return terrain;
}

// On a slope the sole targets lie on the ground (their z axis is its normal) with the plan's heading kept; where
// the map has no ground, and without a map, they are level.
TEST(WaypointSpecTest, SoleTargetsLieOnTheTerrainsNormal) {
  const TerrainMap slope = Slope(10.0);
  const Eigen::Vector3d normal(-std::sin(10.0 * M_PI / 180.0), 0.0, std::cos(10.0 * M_PI / 180.0));
  const FootstepPlan plan = test::StraightPlan(2, 0.2);
  const auto level = MakeWaypointSpecs(plan, TrajectoryOptimizerOptions());
  const auto tilted = MakeWaypointSpecs(plan, TrajectoryOptimizerOptions(), &slope);
  ASSERT_EQ(level.size(), tilted.size());
  for (std::size_t t = 0; t < tilted.size(); ++t) {
    for (std::size_t c = 0; c < tilted[t].contacts.size(); ++c) {
      const Eigen::Matrix3d R = tilted[t].contacts[c].X_WF.rotation();
      EXPECT_LT((R.col(2) - normal).norm(), 1e-6) << tilted[t].label;
      EXPECT_NEAR(std::atan2(R(1, 0), R(0, 0)), 0.0, 1e-9);  // heading kept
      EXPECT_TRUE(level[t].contacts[c].X_WF.rotation().isIdentity(1e-12));
      EXPECT_EQ(tilted[t].contacts[c].X_WF.translation(), level[t].contacts[c].X_WF.translation());
    }
  }
  // A turned foot keeps its heading: the sole's x axis projects onto the plan's yaw.
  const FootPose turned{0.3, 0.0, 0.0, 0.5};
  const Eigen::Matrix3d R = SoleTargetPose(turned, &slope).rotation();
  EXPECT_LT((R.col(2) - normal).norm(), 1e-6);
  EXPECT_NEAR(std::atan2(R(1, 0), R(0, 0)), 0.5, 0.02);
  // Off the map: level.
  EXPECT_TRUE(SoleTargetPose({5.0, 0.0, 0.0, 0.0}, &slope).rotation().isIdentity(1e-12));
  // The fit spans the footprint: level ground whose cells alternate 5 mm up and down, each with a normal tilted
  // 10 degrees (as perceived cells may be), lays the sole within a degree of level.
  TerrainMap noisy(Eigen::Vector2d(-1.0, -1.0), 40, 40, 0.05);
  for (int row = 0; row < noisy.rows(); ++row) {
    for (int col = 0; col < noisy.cols(); ++col) {
      noisy.SetCell(col, row, (col + row) % 2 == 0 ? 0.005 : -0.005, normal, 1.0);
    }
  }
  EXPECT_GT(SoleTargetPose({0.0, 0.0, 0.0, 0.0}, &noisy).rotation()(2, 2), std::cos(M_PI / 180.0));
}

// The whole-body solve on the slope stands its soles on it: the solution meets the tilted targets.
TEST(TrajectoryProblemTest, OnASlopeTheSolvedSolesLieOnTheGround) {
  const TerrainMap slope = Slope(10.0);
  FootstepPlan plan = test::StraightPlan(1, 0.2);
  for (PlannedStep& step : plan.steps) step.pose.z = step.pose.x * std::tan(10.0 * M_PI / 180.0);
  const TrajectoryOptimizerOptions options;
  const WholeBodyTrajectory trajectory = OptimizeWholeBodyTrajectory(test::Humanoid(), plan, {}, options, &slope);
  ASSERT_TRUE(trajectory.found) << trajectory.report.message;
  const auto model = test::Humanoid();
  const auto specs = MakeWaypointSpecs(plan, options, &slope);
  ASSERT_EQ(trajectory.waypoints.size(), specs.size());
  multibody::Data data(*model);
  for (std::size_t t = 0; t < specs.size(); ++t) {
    multibody::ForwardKinematics(*model, data, trajectory.waypoints[t].q);
    for (const WaypointContact& c : specs[t].contacts) {
      const Eigen::Matrix3d R = multibody::FramePose(*model, data, model->GetFrameIndex(c.frame)).rotation();
      EXPECT_LT((R.col(2) - c.X_WF.rotation().col(2)).norm(), 1e-3) << specs[t].label << " " << c.frame;
      EXPECT_GT(R(2, 0), 0.1);  // the toe points uphill
    }
  }
}

TEST(TrajectoryProblemTest, EveryCostAndConstraintHasExactGradientsAtTheWarmStart) {
  const auto model = test::Humanoid();
  TrajectoryOptimizerOptions options;
  const auto specs = MakeWaypointSpecs(test::StraightPlan(1, 0.2), options);
  // A bar over the path close to the head, so collision terms are active.
  const std::vector<EnvironmentBox> bar = {
      {"bar", Eigen::Vector3d(0.1, 2.0, 0.1), multibody::Pose(Eigen::Matrix3d::Identity(), Eigen::Vector3d(0.1, 0, 1.45))}};
  const TrajectoryProblem problem(model, specs, bar, options);
  const Eigen::VectorXd x = problem.DecisionVector(problem.WarmStart());
  const auto check = optimization::CheckGradients(problem.program(), x, 1e-5);
  EXPECT_TRUE(check.passed) << check.ToString();
}

void ExpectSolutionHoldsTheConstraints(const WholeBodyTrajectory& trajectory, const FootstepPlan& plan,
                                       const TrajectoryOptimizerOptions& options) {
  const auto model = test::Humanoid();
  const auto specs = MakeWaypointSpecs(plan, options);
  ASSERT_EQ(trajectory.waypoints.size(), specs.size());
  for (std::size_t t = 0; t < specs.size(); ++t) {
    const WholeBodyWaypoint& w = trajectory.waypoints[t];
    SCOPED_TRACE(w.label);
    for (const WaypointContact& c : specs[t].contacts) {
      const Eigen::VectorXd e = FramePoseError(model, c.frame, c.X_WF).Eval(w.q);
      EXPECT_LE(e.head<3>().norm(), 1e-4) << c.frame;
      EXPECT_LE(e.tail<3>().norm(), 1e-3) << c.frame;
    }
    multibody::Data data(*model);
    const Eigen::Vector3d com = multibody::CenterOfMass(*model, data, w.q);
    EXPECT_LE((specs[t].polygon_A * com.head<2>() - specs[t].polygon_b).maxCoeff(), 1e-6);
    EXPECT_GE(w.min_clearance, options.d_safe - 0.01);
    EXPECT_TRUE(multibody::IsWithinPositionLimits(*model, w.q, 1e-6));
    if (t > 0) {
      const double dt = w.time - trajectory.waypoints[t - 1].time;
      const Eigen::VectorXd dq = w.q - trajectory.waypoints[t - 1].q;
      for (int j = 1; j < static_cast<int>(model->joints().size()); ++j) {
        if (model->joint(j).nq != 1) continue;
        EXPECT_LE(std::abs(dq(model->joint(j).idx_q)), model->joint(j).velocity_limit * dt + 1e-6) << model->joint(j).name;
      }
    }
  }
}

TEST(OptimizeWholeBodyTrajectoryTest, SolvesAStraightPlanWithinEveryConstraint) {
  const auto model = test::Humanoid();
  const FootstepPlan plan = test::StraightPlan(3, 0.2);
  TrajectoryOptimizerOptions options;
  const WholeBodyTrajectory trajectory = OptimizeWholeBodyTrajectory(model, plan, {}, options);
  ASSERT_TRUE(trajectory.found) << trajectory.report.message;
  EXPECT_EQ(trajectory.report.windows, 1);
  EXPECT_GT(trajectory.report.iterations, 0);
  ExpectSolutionHoldsTheConstraints(trajectory, plan, options);
}

}  // namespace
}  // namespace cairn::planning

namespace cairn::planning {
namespace {

TEST(OptimizeWholeBodyTrajectoryTest, SlsqpByNameGivesTheSamePostureOnOneStance) {
  const auto model = test::Humanoid();
  // The start stance only (one waypoint), staggered and turned: a symmetric stance has a symmetric stationary
  // point that is a saddle (the pelvis can yaw either way), where a quasi-Newton method that never sees an
  // asymmetric gradient stays.
  FootstepPlan plan = test::StraightPlan(0, 0.2);
  plan.start.left = {0.08, 0.12, 0.0, 0.25};
  TrajectoryOptimizerOptions options;
  const WholeBodyTrajectory ipopt = OptimizeWholeBodyTrajectory(model, plan, {}, options);
  options.solver = "nlopt:SLSQP";
  const WholeBodyTrajectory slsqp = OptimizeWholeBodyTrajectory(model, plan, {}, options);
  ASSERT_TRUE(ipopt.found) << ipopt.report.message;
  ASSERT_TRUE(slsqp.found) << slsqp.report.message;
  EXPECT_EQ(ipopt.report.solver, "ipopt");
  EXPECT_EQ(slsqp.report.solver, "nlopt:LD_SLSQP");
  ASSERT_EQ(ipopt.waypoints.size(), 1u);
  ASSERT_EQ(slsqp.waypoints.size(), 1u);
  EXPECT_NEAR(ipopt.report.objective, slsqp.report.objective, 1e-4 * std::max(1.0, ipopt.report.objective));
  EXPECT_LT((ipopt.waypoints[0].q - slsqp.waypoints[0].q).cwiseAbs().maxCoeff(), 1e-2)
      << "ipopt " << ipopt.waypoints[0].q.transpose() << "\nslsqp " << slsqp.waypoints[0].q.transpose();
  EXPECT_LT((ipopt.waypoints[0].com - slsqp.waypoints[0].com).norm(), 1e-4);
}

TEST(OptimizeWholeBodyTrajectoryTest, AStanceOutOfReachIsAResultThatNamesTheStance) {
  const auto model = test::Humanoid();
  FootstepPlan plan = test::StraightPlan(2, 0.2);
  plan.steps[0].pose.x = 1.5;  // the right foot's first step lands 1.5 m ahead
  TrajectoryOptimizerOptions options;
  options.max_iterations = 150;
  const WholeBodyTrajectory trajectory = OptimizeWholeBodyTrajectory(model, plan, {}, options);
  EXPECT_FALSE(trajectory.found);
  EXPECT_FALSE(trajectory.report.success);
  ASSERT_FALSE(trajectory.report.violations.empty()) << trajectory.report.message;
  EXPECT_NE(trajectory.report.violations.front().find("stance 1 start, "), std::string::npos)
      << trajectory.report.message;
  EXPECT_NE(trajectory.report.message.find("most violated: stance 1 start"), std::string::npos)
      << trajectory.report.message;
  EXPECT_EQ(trajectory.waypoints.size(), 5u);  // the best point is still returned
}

TEST(OptimizeWholeBodyTrajectoryTest, AMissingPlanIsAResultNotAnError) {
  FootstepPlan plan;
  plan.reason = "goal unreachable";
  const WholeBodyTrajectory trajectory = OptimizeWholeBodyTrajectory(test::Humanoid(), plan, {});
  EXPECT_FALSE(trajectory.found);
  EXPECT_EQ(trajectory.report.status, "no footstep plan");
  EXPECT_NE(trajectory.report.message.find("goal unreachable"), std::string::npos);
  TrajectoryOptimizerOptions bad;
  bad.d_safe = -1.0;
  CAIRN_EXPECT_THROWS_WITH(OptimizeWholeBodyTrajectory(test::Humanoid(), test::StraightPlan(1, 0.2), {}, bad),
                           std::invalid_argument, "d_safe is -1");
}

// The largest rotation of the floating base between consecutive waypoints, rad.
double LargestWaistRotation(const WholeBodyTrajectory& trajectory) {
  double largest = 0.0;
  for (std::size_t i = 1; i < trajectory.waypoints.size(); ++i) {
    const Eigen::VectorXd& a = trajectory.waypoints[i - 1].q;
    const Eigen::VectorXd& b = trajectory.waypoints[i].q;
    const Eigen::Quaterniond qa(a(3), a(4), a(5), a(6)), qb(b(3), b(4), b(5), b(6));
    largest = std::max(largest, qa.angularDistance(qb));
  }
  return largest;
}

TEST(OptimizeWholeBodyTrajectoryTest, TheOrientationSmoothnessTermCalmsTheWaistWithinEveryConstraint) {
  const auto model = test::Humanoid();
  const FootstepPlan plan = test::StraightPlan(3, 0.2);
  TrajectoryOptimizerOptions options;
  options.base_rotation_smoothness_weight = 0.0;
  const WholeBodyTrajectory free = OptimizeWholeBodyTrajectory(model, plan, {}, options);
  options.base_rotation_smoothness_weight = 1.0;
  const WholeBodyTrajectory smooth = OptimizeWholeBodyTrajectory(model, plan, {}, options);
  ASSERT_TRUE(free.found) << free.report.message;
  ASSERT_TRUE(smooth.found) << smooth.report.message;
  ExpectSolutionHoldsTheConstraints(smooth, plan, options);
  const double free_swing = LargestWaistRotation(free), smooth_swing = LargestWaistRotation(smooth);
  std::printf("largest waist rotation between waypoints: %.1f deg free, %.1f deg smoothed; objective %.4f, %.4f\n",
              free_swing * 180.0 / M_PI, smooth_swing * 180.0 / M_PI, free.report.objective, smooth.report.objective);
  EXPECT_LT(smooth_swing, 0.5 * free_swing);
  TrajectoryOptimizerOptions bad;
  bad.base_rotation_smoothness_weight = -1.0;
  CAIRN_EXPECT_THROWS_WITH(ValidateTrajectoryOptimizerOptions(bad), std::invalid_argument,
                           "base_rotation_smoothness_weight is -1; it must be finite and >= 0");
}

TEST(OptimizeWholeBodyTrajectoryTest, ARecedingWindowKeepsContinuityAndTheConstraints) {
  const auto model = test::Humanoid();
  const FootstepPlan plan = test::StraightPlan(3, 0.2);
  TrajectoryOptimizerOptions options;
  options.window_stances = 2;
  const WholeBodyTrajectory trajectory = OptimizeWholeBodyTrajectory(model, plan, {}, options);
  ASSERT_TRUE(trajectory.found) << trajectory.report.message;
  EXPECT_EQ(trajectory.report.windows, 3);
  ExpectSolutionHoldsTheConstraints(trajectory, plan, options);
  // Each waypoint is returned by exactly one window, so the report's torque term is the waypoints' sum.
  double sum = 0.0;
  for (const WholeBodyWaypoint& w : trajectory.waypoints) {
    EXPECT_GT(w.torque_cost, 0.0) << w.label;
    sum += w.torque_cost;
  }
  EXPECT_NEAR(sum, trajectory.report.torque_cost, 1e-12 * trajectory.report.torque_cost);
}

}  // namespace
}  // namespace cairn::planning
