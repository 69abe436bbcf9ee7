#include <cairn/planning/stabilization/pelvis_pose_solver.h>

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <cairn/multibody/center_of_mass.h>
#include <cairn/multibody/data.h>
#include <cairn/multibody/kinematics.h>

#include "../trajectory/test_robot.h"
#include "expect_throws.h"

namespace cairn::planning {
namespace {

TEST(PelvisPoseSolverTest, PutsTheSolesTheWaistAndTheComWhereAsked) {
  const auto model = test::Humanoid();
  const multibody::Model& m = *model;
  const Eigen::VectorXd seed = test::BentKneePosture(m);
  multibody::Data data(m);
  multibody::ForwardKinematics(m, data, seed);
  const int l = m.GetFrameIndex("l_sole"), r = m.GetFrameIndex("r_sole");
  // The left foot 0.2 m ahead and turned 10 degrees, the right one lifted 5 cm; the waist lower and turned 5 deg.
  const multibody::Pose X_L(Eigen::AngleAxisd(0.17, Eigen::Vector3d::UnitZ()).toRotationMatrix(),
                            multibody::FramePose(m, data, l).translation() + Eigen::Vector3d(0.2, 0.0, 0.0));
  const multibody::Pose X_R(multibody::FramePose(m, data, r).rotation(),
                            multibody::FramePose(m, data, r).translation() + Eigen::Vector3d(0.0, 0.0, 0.05));
  const Eigen::Matrix3d R_base = Eigen::AngleAxisd(0.09, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  const Eigen::Vector2d com_target(0.08, 0.03);
  const PelvisPoseSolver solver(model, "l_sole", "r_sole");
  const PelvisPoseResult result = solver.Solve(seed, com_target, R_base, 0.78, X_L, X_R);
  EXPECT_LT(result.sole_error, 1e-8);
  EXPECT_LT(result.com_error, 1e-6);
  multibody::ForwardKinematics(m, data, result.q);
  EXPECT_LT((multibody::FramePose(m, data, l).translation() - X_L.translation()).norm(), 1e-7);
  EXPECT_LT((multibody::FramePose(m, data, l).rotation() - X_L.rotation()).norm(), 1e-7);
  EXPECT_LT((multibody::FramePose(m, data, r).translation() - X_R.translation()).norm(), 1e-7);
  EXPECT_NEAR(result.q(2), 0.78, 1e-12);
  const Eigen::Quaterniond quat(result.q(3), result.q(4), result.q(5), result.q(6));
  EXPECT_TRUE(quat.toRotationMatrix().isApprox(R_base, 1e-9));
  EXPECT_TRUE(multibody::CenterOfMass(m, data, result.q).head<2>().isApprox(com_target, 1e-5));
  // The upper body keeps the seed's joint angles.
  const int elbow = m.joint(m.GetJointIndex("l_elbow")).idx_q;
  EXPECT_EQ(result.q(elbow), seed(elbow));
}

TEST(PelvisPoseSolverTest, RefusesBadInputWithTheFix) {
  const auto model = test::Humanoid();
  CAIRN_EXPECT_THROWS_WITH(PelvisPoseSolver(model, "l_sole", "no_such_frame"), std::invalid_argument, "has no frame 'no_such_frame'");
  CAIRN_EXPECT_THROWS_WITH(PelvisPoseSolver(model, "l_sole", "l_palm"), std::invalid_argument, "is not on a leg of six joints");
  const PelvisPoseSolver solver(model, "l_sole", "r_sole");
  const multibody::Pose X;
  CAIRN_EXPECT_THROWS_WITH(
      solver.Solve(Eigen::VectorXd::Zero(3), Eigen::Vector2d::Zero(), Eigen::Matrix3d::Identity(), 0.8, X, X),
      std::invalid_argument, "finite coordinates");
  CAIRN_EXPECT_THROWS_WITH(
      solver.Solve(test::BentKneePosture(*model), Eigen::Vector2d::Zero(), 2.0 * Eigen::Matrix3d::Identity(), 0.8, X, X),
      std::invalid_argument, "must be a rotation matrix");
}

}  // namespace
}  // namespace cairn::planning
