// The ZMP of a motion from the full model: static, cart-table, bad input.
#include <gtest/gtest.h>

#include <cairn/multibody/center_of_mass.h>
#include <cairn/multibody/data.h>
#include <cairn/planning/stabilization/motion_zmp.h>
#include <cairn/planning/stabilization/support_polygon.h>

#include "../trajectory/test_robot.h"
#include "expect_throws.h"

namespace cairn::planning {
namespace {

TEST(MotionZmpTest, StandingStillPutsTheZmpUnderTheCom) {
  const auto model = test::Humanoid();
  const Eigen::VectorXd q = test::BentKneePosture(*model);
  multibody::Data data(*model);
  const Eigen::Vector3d com = multibody::CenterOfMass(*model, data, q);
  const auto zmp = ComputeMotionZmp(*model, std::vector<Eigen::VectorXd>(5, q), 0.01, {0.0});
  for (const Eigen::Vector2d& p : zmp) EXPECT_LT((p - com.head<2>()).norm(), 1e-9);
}

TEST(MotionZmpTest, AConstantlyAcceleratedBodyHasTheCartTableZmp) {
  // The whole robot translated with x'' = 1.5 m/s^2, y'' = -0.5 m/s^2 (no rotation, no angular momentum):
  // p = c - (z_c / g) c'' exactly, since central differences of a quadratic are exact.
  const auto model = test::Humanoid();
  const Eigen::VectorXd q0 = test::BentKneePosture(*model);
  const double dt = 0.01;
  std::vector<Eigen::VectorXd> q(21, q0);
  for (std::size_t k = 0; k < q.size(); ++k) {
    const double t = dt * static_cast<double>(k);
    q[k][0] += 0.5 * 1.5 * t * t;
    q[k][1] += 0.5 * -0.5 * t * t;
  }
  multibody::Data data(*model);
  const double ground = 0.05;
  const auto zmp = ComputeMotionZmp(*model, q, dt, {ground});
  // Away from the ends (their one-sided velocity differences are first order).
  for (std::size_t k = 2; k + 2 < q.size(); ++k) {
    const Eigen::Vector3d c = multibody::CenterOfMass(*model, data, q[k]);
    const double gain = (c.z() - ground) / 9.81;
    EXPECT_NEAR(zmp[k].x(), c.x() - gain * 1.5, 1e-6) << k;
    EXPECT_NEAR(zmp[k].y(), c.y() + gain * 0.5, 1e-6) << k;
  }
}

TEST(MotionZmpTest, RejectsBadInput) {
  const auto model = test::Humanoid();
  const Eigen::VectorXd q = test::BentKneePosture(*model);
  CAIRN_EXPECT_THROWS_WITH(ComputeMotionZmp(*model, {q, q}, 0.01, {0.0}), std::invalid_argument,
                           "2 samples given; at least 3 are needed");
  CAIRN_EXPECT_THROWS_WITH(ComputeMotionZmp(*model, {q, q, q}, 0.0, {0.0}), std::invalid_argument,
                           "period 0 s must be positive and finite");
  CAIRN_EXPECT_THROWS_WITH(ComputeMotionZmp(*model, {q, q, Eigen::VectorXd::Zero(3)}, 0.01, {0.0}),
                           std::invalid_argument, "sample 2 must have");
  CAIRN_EXPECT_THROWS_WITH(ComputeMotionZmp(*model, {q, q, q}, 0.01, {0.0, 0.0}), std::invalid_argument,
                           "2 ground heights given for 3 samples; give 1 or 3");
}

TEST(SupportPolygonTest, HullOfTwoSolesAndSignedMargins) {
  const multibody::Pose left(Eigen::Matrix3d::Identity(), Eigen::Vector3d(0.0, 0.1, 0.0));
  const multibody::Pose right(Eigen::Matrix3d::Identity(), Eigen::Vector3d(0.0, -0.1, 0.0));
  const auto hull = SupportPolygon({left, right}, 0.24, 0.14);
  EXPECT_EQ(hull.size(), 4u);
  EXPECT_NEAR(SupportMargin(hull, Eigen::Vector2d(0.0, 0.0)), 0.12, 1e-12);   // to the toe and heel edges
  EXPECT_NEAR(SupportMargin(hull, Eigen::Vector2d(0.0, 0.16)), 0.01, 1e-12);  // 1 cm inside the left edge
  EXPECT_NEAR(SupportMargin(hull, Eigen::Vector2d(0.22, 0.0)), -0.10, 1e-12);  // 10 cm ahead of the toes
  EXPECT_EQ(SupportMargin({}, Eigen::Vector2d::Zero()), -std::numeric_limits<double>::infinity());
}

}  // namespace
}  // namespace cairn::planning
