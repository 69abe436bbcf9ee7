// InverseKinematics on the CHOLMOD least-squares solver: foot poses and COM of a standing humanoid.
#include <gtest/gtest.h>

#include <cairn/multibody/center_of_mass.h>
#include <cairn/multibody/data.h>
#include <cairn/multibody/kinematics.h>
#include <cairn/planning/trajectory/inverse_kinematics.h>

#include "expect_throws.h"
#include "test_robot.h"

namespace cairn::planning {
namespace {

multibody::Pose SolePose(double x, double y, double yaw) {
  return multibody::Pose(Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()).toRotationMatrix(), Eigen::Vector3d(x, y, 0.0));
}

TEST(InverseKinematicsTest, PlacesBothSolesAndTheComFromABentKneeGuess) {
  const auto model = test::Humanoid();
  InverseKinematics ik(model);
  ik.AddFramePoseTarget("l_sole", SolePose(0.15, 0.1, 0.1));
  ik.AddFramePoseTarget("r_sole", SolePose(0.0, -0.1, 0.0));
  ik.AddCenterOfMassTarget(Eigen::Vector2d(0.0, -0.08));
  ik.AddZeroRollTarget("waist_link");
  ik.SetPosture(test::BentKneePosture(*model));
  const InverseKinematicsResult result = ik.Solve(test::BentKneePosture(*model));
  ASSERT_TRUE(result.success) << result.message;
  EXPECT_LE(result.max_position_error, 1e-4);
  EXPECT_LE(result.max_rotation_error, 1e-3);
  multibody::Data data(*model);
  const Eigen::Vector3d com = multibody::CenterOfMass(*model, data, result.q);
  EXPECT_NEAR(com.x(), 0.0, 0.01);
  EXPECT_NEAR(com.y(), -0.08, 0.01);
  EXPECT_NEAR(result.q.segment<4>(3).norm(), 1.0, 1e-12);
}

TEST(InverseKinematicsTest, ReportsAnUnreachableTargetByName) {
  const auto model = test::Humanoid();
  InverseKinematics ik(model);
  ik.AddFramePoseTarget("l_sole", SolePose(1.5, 0.1, 0.0));
  ik.AddFramePoseTarget("r_sole", SolePose(0.0, -0.1, 0.0));
  ik.SetPosture(test::BentKneePosture(*model));
  const InverseKinematicsResult result = ik.Solve(test::BentKneePosture(*model));
  EXPECT_FALSE(result.success);
  EXPECT_GT(result.max_position_error, 0.1);
  EXPECT_NE(result.message.find("pose_error("), std::string::npos) << result.message;
}

TEST(InverseKinematicsTest, RejectsBadArguments) {
  const auto model = test::Humanoid();
  InverseKinematics ik(model);
  CAIRN_EXPECT_THROWS_WITH(ik.AddFramePoseTarget("l_sole", multibody::Pose(), -1.0), std::invalid_argument,
                           "weight of the pose target of 'l_sole' is -1");
  CAIRN_EXPECT_THROWS_WITH(ik.Solve(Eigen::VectorXd::Zero(3)), std::invalid_argument, "the guess has 3 entries");
}

}  // namespace
}  // namespace cairn::planning
