// JointTrajectory: a CSV reference for the plant's PD control, interpolated linearly, with one-line errors.

#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include <cairn/multibody/configuration.h>
#include <cairn/multibody/plant/joint_trajectory.h>

#include "expect_throws.h"
#include "test_models.h"
#include "test_paths.h"

namespace cairn::multibody {
namespace {

std::string Write(const std::string& name, const std::string& text) {
  const std::string path = std::string(CAIRN_BINARY_DIR) + "/" + name;
  std::ofstream(path) << text;
  return path;
}

TEST(JointTrajectoryTest, InterpolatesLinearlyAndHoldsOutside) {
  const Model model = test::LoadRobot(test::HumanoidUrdf(), true);
  const JointTrajectory trajectory = JointTrajectory::LoadCsv(
      model, Write("traj_ok.csv", "time, r_elbow, l_knee\n0.5, 0.0, 0.2\n1.5, -1.0, 0.4\n"));
  EXPECT_EQ(trajectory.num_rows(), 2u);
  EXPECT_DOUBLE_EQ(trajectory.end_time(), 1.5);
  const Eigen::VectorXd base = NeutralConfiguration(model);
  const Joint& elbow = model.joint(model.GetJointIndex("r_elbow"));
  const Joint& knee = model.joint(model.GetJointIndex("l_knee"));
  Eigen::VectorXd q, v;
  trajectory.Evaluate(1.0, base, &q, &v);
  EXPECT_DOUBLE_EQ(q[elbow.idx_q], -0.5);
  EXPECT_DOUBLE_EQ(q[knee.idx_q], 0.3);
  EXPECT_DOUBLE_EQ(v[elbow.idx_v], -1.0);
  EXPECT_DOUBLE_EQ(v[knee.idx_v], 0.2);
  EXPECT_DOUBLE_EQ(q[2], base[2]);  // the base and the other joints keep q_base's values
  trajectory.Evaluate(0.0, base, &q, &v);
  EXPECT_DOUBLE_EQ(q[knee.idx_q], 0.2);
  EXPECT_DOUBLE_EQ(v[knee.idx_v], 0.0);
  trajectory.Evaluate(9.0, base, &q, &v);
  EXPECT_DOUBLE_EQ(q[elbow.idx_q], -1.0);
  EXPECT_DOUBLE_EQ(v[elbow.idx_v], 0.0);
}

TEST(JointTrajectoryTest, RejectsBadFilesWithTheLine) {
  const Model model = test::LoadRobot(test::HumanoidUrdf(), true);
  CAIRN_EXPECT_THROWS_WITH(JointTrajectory::LoadCsv(model, Write("traj_head.csv", "t,r_elbow\n0,0\n")),
                           std::invalid_argument, "line 1: the header must start with 'time'");
  CAIRN_EXPECT_THROWS_WITH(JointTrajectory::LoadCsv(model, Write("traj_joint.csv", "time,r_elbo\n0,0\n")),
                           std::invalid_argument, "names 'r_elbo', not a joint");
  CAIRN_EXPECT_THROWS_WITH(JointTrajectory::LoadCsv(model, Write("traj_nan.csv", "time,r_elbow\n0,0\n1,nan\n")),
                           std::invalid_argument, "line 3: field 2 ('nan') is not a finite number");
  CAIRN_EXPECT_THROWS_WITH(JointTrajectory::LoadCsv(model, Write("traj_time.csv", "time,r_elbow\n1,0\n1,0\n")),
                           std::invalid_argument, "line 3: time 1 does not increase");
  CAIRN_EXPECT_THROWS_WITH(JointTrajectory::LoadCsv(model, Write("traj_limit.csv", "time,r_elbow\n0,1.5\n")),
                           std::invalid_argument, "joint 'r_elbow' at 1.5 is outside its limits");
  CAIRN_EXPECT_THROWS_WITH(JointTrajectory::LoadCsv(model, Write("traj_fields.csv", "time,r_elbow\n0\n")),
                           std::invalid_argument, "line 2: 1 fields, but the header has 2");
  CAIRN_EXPECT_THROWS_WITH(JointTrajectory::LoadCsv(model, Write("traj_rows.csv", "time,r_elbow\n")),
                           std::invalid_argument, "no rows");
  CAIRN_EXPECT_THROWS_WITH(JointTrajectory::LoadCsv(model, std::string(CAIRN_BINARY_DIR) + "/no_such.csv"),
                           std::invalid_argument, "does not exist");
}

}  // namespace
}  // namespace cairn::multibody
