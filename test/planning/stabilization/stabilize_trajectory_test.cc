// Interpolation and stabilisation of a real optimised trajectory: the stabilisers lower the full model's ZMP error.
#include <gtest/gtest.h>

#include <cmath>
#include <cstddef>

#include <cairn/multibody/data.h>
#include <cairn/multibody/kinematics.h>
#include <cairn/planning/stabilization/interpolation_knots.h>
#include <cairn/planning/stabilization/stabilize_trajectory.h>

#include "expect_throws.h"
#include "flat_trajectory.h"

namespace cairn::planning {
namespace {

TEST(InterpolationKnotsTest, ContactTimingHoldsTheDoubleSupportAndInsertsTouchDowns) {
  const WholeBodyTrajectory& trajectory = test::FlatTrajectory();
  ASSERT_TRUE(trajectory.found) << trajectory.report.message;
  ASSERT_EQ(trajectory.waypoints.size(), 9u);
  StabilizerOptions options;
  options.contact_timing = true;
  const auto knots = MakeInterpolationKnots(test::Humanoid(), trajectory, options);
  // Per step: touch-down (or start), lift-off, mid-swing; then the last touch-down and the end.
  ASSERT_EQ(knots.size(), 4u * 3u + 2u);
  EXPECT_EQ(knots[0].label, "start");
  EXPECT_EQ(knots[1].label, "stance 0 lift-off");
  EXPECT_NEAR(knots[1].time, 0.2, 1e-9);  // t_ds
  EXPECT_NEAR(knots[2].time, 0.5, 1e-9);  // t_ds + t_sw / 2
  EXPECT_EQ(knots[3].label, "stance 1 touch-down");
  EXPECT_NEAR(knots[3].time, 0.8, 1e-9);
  EXPECT_EQ(knots[2].contacts, kLeftSoleContact);  // the right foot swings first
  // The reference ZMP stays over the stance foot until touch-down, then crosses in the double support.
  EXPECT_LT((knots[3].com - knots[2].com).norm(), 1e-12);
  EXPECT_LT((knots[4].com - trajectory.waypoints[2].com.head<2>()).norm(), 1e-9);
  // The posture is held through the double support (the feet do not slide).
  EXPECT_LT((knots[3].q - knots[4].q).cwiseAbs().maxCoeff(), 1e-12);
  EXPECT_NEAR(knots.back().time, trajectory.waypoints.back().time + 0.2, 1e-9);
}

TEST(InterpolationKnotsTest, RejectsATrajectoryItCannotInterpolate) {
  WholeBodyTrajectory missing;
  missing.report.message = "infeasible";
  CAIRN_EXPECT_THROWS_WITH(MakeInterpolationKnots(test::Humanoid(), missing, StabilizerOptions()),
                           std::invalid_argument, "the whole-body trajectory was not found (infeasible)");
  WholeBodyTrajectory trajectory = test::FlatTrajectory();
  trajectory.waypoints.pop_back();
  StabilizerOptions timed;
  timed.contact_timing = true;
  CAIRN_EXPECT_THROWS_WITH(MakeInterpolationKnots(test::Humanoid(), trajectory, timed),
                           std::invalid_argument, "8 waypoints cannot alternate stance start / mid-swing");
  trajectory = test::FlatTrajectory();
  trajectory.waypoints[3].time = trajectory.waypoints[2].time;
  CAIRN_EXPECT_THROWS_WITH(MakeInterpolationKnots(test::Humanoid(), trajectory, StabilizerOptions()),
                           std::invalid_argument, "waypoint 3 at 0.8 s does not come after waypoint 2 at 0.8 s");
  StabilizerOptions options;
  options.waist_frame = "torso_link";
  CAIRN_EXPECT_THROWS_WITH(MakeInterpolationKnots(test::Humanoid(), test::FlatTrajectory(), options),
                           std::invalid_argument, "has no frame 'torso_link'");
}

// What the compensation achieves on the 0.8 s steps of the test plan (measured, not what a walk needs): it
// lowers the full model's ZMP error and brings the ZMP closer to the support polygon, but the Hermite motion's
// stop at every knot (the swing leg stops at mid-swing) and the optimiser's waist swings are far from the linear
// ZMP equation, so the error stays decimetres and the ZMP leaves the polygon (see docs/walk.md).
void ExpectLowerError(const StabilizedTrajectory& out) {
  const StabilizationReport& r = out.report;
  ASSERT_TRUE(r.success) << r.message;
  std::cout << "[ measured ] " << r.message << "; support margin " << r.min_support_margin_before << " -> "
            << r.min_support_margin_after << " m, leg IK error " << r.max_ik_error << " m, joint limits "
            << (r.joint_limits_held ? "held" : "violated") << ", " << r.seconds << " s\n";
  EXPECT_LT(r.rms_error_after, 0.6 * r.rms_error_before) << r.message;
  EXPECT_LT(r.max_error_after, 0.6 * r.max_error_before) << r.message;
  EXPECT_GE(r.iterations, 1);
  EXPECT_LT(r.max_ik_error, 1e-4);
  EXPECT_GT(r.min_support_margin_after, r.min_support_margin_before);
  EXPECT_EQ(out.q.size(), out.zmp.size());
  EXPECT_EQ(out.q.size(), out.v.size());
}

TEST(StabilizeTrajectoryTest, InterpolationOnlyReportsTheErrorOfTheStaticPlan) {
  StabilizerOptions options;
  options.method = "none";
  const StabilizedTrajectory out = StabilizeTrajectory(test::Humanoid(), test::FlatTrajectory(), options);
  ASSERT_TRUE(out.report.success) << out.report.message;
  // 3.2 s at 200 Hz (4 steps of 0.8 s).
  EXPECT_EQ(out.q.size(), 641u);
  EXPECT_NEAR(out.duration(), 3.2, 1e-9);
  EXPECT_EQ(out.report.iterations, 0);
  EXPECT_EQ(out.report.rms_error_after, out.report.rms_error_before);
  // A statically planned motion at walking speed is not dynamically balanced: centimetres of ZMP error.
  EXPECT_GT(out.report.max_error_before, 0.01);
  std::cout << "[ measured ] " << out.report.message << "\n";
}

TEST(StabilizeTrajectoryTest, CompensationLowersTheZmpErrorOfAnOptimisedFlatTrajectory) {
  const StabilizedTrajectory out = StabilizeTrajectory(test::Humanoid(), test::FlatTrajectory(), StabilizerOptions());
  ExpectLowerError(out);
}

// With contact timing (soles on the ground from touch-down to lift-off, the swing sole on its path), the upright
// waist lowered 6 cm (bent knees) and the cart-table start, the compensation converges to a ZMP inside the support
// polygons, far below the thesis' interpolation of the same waypoints.
TEST(StabilizeTrajectoryTest, CompensationWithContactTimingAndBentKneesConvergesInsideTheSupport) {
  StabilizerOptions options;
  options.contact_timing = true;
  options.waist_orientation = "upright";
  options.cart_table_start = true;
  options.crouch = 0.06;
  const StabilizedTrajectory timed = StabilizeTrajectory(test::Humanoid(), test::FlatTrajectory(), options);
  const StabilizedTrajectory thesis = StabilizeTrajectory(test::Humanoid(), test::FlatTrajectory(), StabilizerOptions());
  ASSERT_TRUE(timed.report.success) << timed.report.message;
  std::cout << "[ measured ] contact timing: " << timed.report.message << "\n";
  EXPECT_LT(timed.report.rms_error_after, 0.01);
  EXPECT_LT(timed.report.rms_error_after, thesis.report.rms_error_after);
  EXPECT_GT(timed.report.min_support_margin_after, 0.0);
  EXPECT_EQ(timed.report.unsupported_samples_after, 0);
}

// With a landing phase the swing sole stops landing_height above its touch-down pose, landing_time before
// touch-down, and comes down at the constant speed landing_height / landing_time; without one it is still falling
// fast just before touch-down (the quadratic approach that lands a sole that runs low at 15 cm/s in the plant).
TEST(StabilizeTrajectoryTest, ALandingPhaseBringsTheSwingSoleDownSlowlyAtTheEnd) {
  StabilizerOptions options;
  options.method = "none";
  options.contact_timing = true;
  options.waist_orientation = "upright";
  options.crouch = 0.06;
  const auto model = test::Humanoid();
  const StabilizedTrajectory plain = StabilizeTrajectory(model, test::FlatTrajectory(), options);
  options.landing_height = 0.01;
  options.landing_time = 0.15;
  const StabilizedTrajectory landing = StabilizeTrajectory(model, test::FlatTrajectory(), options);
  ASSERT_EQ(plain.q.size(), landing.q.size());
  const double period = landing.period;
  multibody::Data data(*model);
  const auto sole = [&](const StabilizedTrajectory& out, std::size_t k, int foot) {
    multibody::ForwardKinematics(*model, data, out.q[k]);
    return multibody::FramePose(*model, data, model->GetFrameIndex(foot == 0 ? "l_sole" : "r_sole")).translation();
  };
  int touchdowns = 0;
  for (int foot = 0; foot < 2; ++foot) {
    for (std::size_t k = 1; k < landing.q.size(); ++k) {
      const bool down = (landing.contacts[k] >> foot) & 1, was_down = (landing.contacts[k - 1] >> foot) & 1;
      if (!down || was_down) continue;
      ++touchdowns;
      const Eigen::Vector3d at_touchdown = sole(landing, k, foot);
      const std::size_t hover = k - static_cast<std::size_t>(std::lround(options.landing_time / period));
      const Eigen::Vector3d at_hover = sole(landing, hover, foot);
      EXPECT_NEAR(at_hover.z() - at_touchdown.z(), 0.01, 5e-4) << "foot " << foot << " at " << k * period << " s";
      EXPECT_LT((at_hover - at_touchdown).head<2>().norm(), 5e-4);
      // 50 ms before touch-down: at the landing speed, against about twice that without the landing phase.
      const std::size_t before = k - static_cast<std::size_t>(std::lround(0.05 / period));
      const double speed = (sole(landing, before - 1, foot).z() - sole(landing, before + 1, foot).z()) / (2 * period);
      EXPECT_NEAR(speed, 0.01 / 0.15, 5e-3);
      const double plain_speed = (sole(plain, before - 1, foot).z() - sole(plain, before + 1, foot).z()) / (2 * period);
      EXPECT_GT(plain_speed, 1.5 * speed);
    }
  }
  EXPECT_GE(touchdowns, 2);

  options.landing_time = 0.0;
  CAIRN_EXPECT_THROWS_WITH(StabilizeTrajectory(model, test::FlatTrajectory(), options), std::invalid_argument,
                           "landing_height 0.01 m and landing_time 0 s must be both 0");
  options.landing_time = 0.15;
  options.contact_timing = false;
  CAIRN_EXPECT_THROWS_WITH(StabilizeTrajectory(model, test::FlatTrajectory(), options), std::invalid_argument,
                           "landing_height 0.01 m needs contact_timing");
  options.contact_timing = true;
  options.landing_time = 0.9;
  CAIRN_EXPECT_THROWS_WITH(StabilizeTrajectory(model, test::FlatTrajectory(), options), std::invalid_argument,
                           "landing_time 0.9 s is more than half of the swing", "choose a shorter landing_time");
}

TEST(StabilizeTrajectoryTest, PreviewControlLowersTheZmpErrorOfAnOptimisedFlatTrajectory) {
  StabilizerOptions options;
  options.method = "preview";
  ExpectLowerError(StabilizeTrajectory(test::Humanoid(), test::FlatTrajectory(), options));
}

TEST(StabilizeTrajectoryTest, RejectsBadOptionsAndTooManySamples) {
  StabilizerOptions options;
  options.control_period = 1e-5;
  CAIRN_EXPECT_THROWS_WITH(StabilizeTrajectory(test::Humanoid(), test::FlatTrajectory(), options),
                           std::invalid_argument, "control_period 1e-05 s must be in [0.0001, 0.05]");
  options = StabilizerOptions();
  options.max_iterations = 0;
  CAIRN_EXPECT_THROWS_WITH(StabilizeTrajectory(test::Humanoid(), test::FlatTrajectory(), options),
                           std::invalid_argument, "max_iterations 0 must be in [1, 100]");
  WholeBodyTrajectory long_one = test::FlatTrajectory();
  long_one.waypoints.back().time = 1e4;
  options = StabilizerOptions();
  CAIRN_EXPECT_THROWS_WITH(StabilizeTrajectory(test::Humanoid(), long_one, options), std::invalid_argument,
                           "more than the limit of 200000; lengthen control_period");
}

}  // namespace
}  // namespace cairn::planning
