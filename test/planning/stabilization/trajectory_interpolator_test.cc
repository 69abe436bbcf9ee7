// Hermite and C2 interpolation of knots: waypoints hit with zero velocity, quaternions on the sphere.
#include <gtest/gtest.h>

#include <cmath>

#include <Eigen/Geometry>

#include <cairn/multibody/configuration.h>
#include <cairn/planning/stabilization/trajectory_interpolator.h>

#include "../trajectory/test_robot.h"
#include "expect_throws.h"

namespace cairn::planning {
namespace {

std::vector<InterpolationKnot> ThreeKnots() {
  const auto model = test::Humanoid();
  std::vector<InterpolationKnot> knots(3);
  for (int k = 0; k < 3; ++k) {
    knots[k].time = 0.5 * k;
    knots[k].q = test::BentKneePosture(*model, 0.82 - 0.01 * k);
    knots[k].q[0] = 0.1 * k;
    knots[k].com = Eigen::Vector2d(0.1 * k, 0.02 * k);
    knots[k].contacts = 3;
  }
  // Yaw the base by 30 deg at the middle knot and 60 deg at the last.
  for (int k = 1; k < 3; ++k) {
    const Eigen::Quaterniond r(Eigen::AngleAxisd(0.5235987755982988 * k, Eigen::Vector3d::UnitZ()));
    knots[k].q.segment<4>(3) << r.w(), r.x(), r.y(), r.z();
  }
  return knots;
}

TEST(TrajectoryInterpolatorTest, HermiteHitsTheKnotsWithZeroVelocity) {
  const auto model = test::Humanoid();
  const auto knots = ThreeKnots();
  const TrajectoryInterpolator interpolator(model, knots, "hermite");
  for (const InterpolationKnot& knot : knots) {
    Eigen::VectorXd q, v;
    interpolator.Evaluate(knot.time, &q, &v);
    EXPECT_LT((q - knot.q).cwiseAbs().maxCoeff(), 1e-9);
    EXPECT_LT(v.cwiseAbs().maxCoeff(), 1e-6);
    EXPECT_LT((interpolator.ReferenceZmp(knot.time) - knot.com).norm(), 1e-12);
  }
  // Half-way: the smoothstep is 1/2, the quaternion is the slerp's midpoint (15 deg yaw) and of unit length.
  Eigen::VectorXd q, v;
  interpolator.Evaluate(0.25, &q, &v);
  EXPECT_NEAR(q[0], 0.05, 1e-12);
  const Eigen::Quaterniond half(q[3], q[4], q[5], q[6]);
  EXPECT_NEAR(half.norm(), 1.0, 1e-12);
  EXPECT_NEAR(Eigen::AngleAxisd(half).angle(), 0.2617993877991494, 1e-9);
  // Velocity at the middle of a segment is 1.5 x the mean rate: h'(1/2) = 3/2 over T.
  EXPECT_NEAR(v[5], 1.5 * -0.01 / 0.5, 1e-6);  // the base height's rate, body z = world z under a yaw
  const int knee = model->joint(model->GetJointIndex("l_knee")).idx_v;
  EXPECT_NEAR(v[knee], 1.5 * (knots[1].q[model->joint(model->GetJointIndex("l_knee")).idx_q] -
                              knots[0].q[model->joint(model->GetJointIndex("l_knee")).idx_q]) / 0.5, 1e-9);
  // The base yaw rate (body twist) at mid-segment: 1.5 x 30 deg / 0.5 s.
  EXPECT_NEAR(v[2], 1.5 * 0.5235987755982988 / 0.5, 1e-6);
}

TEST(TrajectoryInterpolatorTest, SplinePassesThroughTheKnotsWithContinuousVelocity) {
  const auto model = test::Humanoid();
  const auto knots = ThreeKnots();
  const TrajectoryInterpolator interpolator(model, knots, "spline");
  for (const InterpolationKnot& knot : knots) {
    const Eigen::VectorXd q = interpolator.Position(knot.time);
    EXPECT_LT(multibody::Difference(*model, q, knot.q).cwiseAbs().maxCoeff(), 1e-9);
  }
  Eigen::VectorXd q0, v0, q1, v1;
  interpolator.Evaluate(0.5 - 1e-7, &q0, &v0);
  interpolator.Evaluate(0.5 + 1e-7, &q1, &v1);
  EXPECT_LT((v1 - v0).cwiseAbs().maxCoeff(), 1e-4);
  // The base height falls linearly through the knots (0.02 m/s), and a natural spline through points on a line
  // is that line: the rate is constant, not Hermite's stop at every knot.
  for (double t : {0.0, 0.25, 0.5, 0.75}) {
    Eigen::VectorXd q, v;
    interpolator.Evaluate(t + 1e-4, &q, &v);
    EXPECT_NEAR(v[5], -0.02, 1e-6) << t;
  }
  const Eigen::Quaterniond middle(q0[3], q0[4], q0[5], q0[6]);
  EXPECT_NEAR(middle.norm(), 1.0, 1e-12);
}

TEST(TrajectoryInterpolatorTest, HoldsBeforeTheFirstAndAfterTheLastKnot) {
  const auto knots = ThreeKnots();
  const TrajectoryInterpolator interpolator(test::Humanoid(), knots);
  Eigen::VectorXd q, v;
  interpolator.Evaluate(5.0, &q, &v);
  EXPECT_LT((q - knots.back().q).cwiseAbs().maxCoeff(), 1e-12);
  EXPECT_LT(v.cwiseAbs().maxCoeff(), 1e-12);
  EXPECT_EQ(interpolator.Contacts(-1.0), 3);
}

TEST(TrajectoryInterpolatorTest, RejectsBadKnots) {
  auto knots = ThreeKnots();
  CAIRN_EXPECT_THROWS_WITH(TrajectoryInterpolator(test::Humanoid(), knots, "linear"), std::invalid_argument,
                           "interpolation 'linear' is unknown; use hermite or spline");
  knots[2].time = 0.5;
  CAIRN_EXPECT_THROWS_WITH(TrajectoryInterpolator(test::Humanoid(), knots), std::invalid_argument,
                           "knot 2 at 0.5 s does not come after knot 1 at 0.5 s");
  knots = ThreeKnots();
  knots[1].q.resize(3);
  CAIRN_EXPECT_THROWS_WITH(TrajectoryInterpolator(test::Humanoid(), knots), std::invalid_argument,
                           "knot 1 needs a finite time and");
  CAIRN_EXPECT_THROWS_WITH(TrajectoryInterpolator(test::Humanoid(), {}), std::invalid_argument,
                           "at least one knot is needed");
}

}  // namespace
}  // namespace cairn::planning
