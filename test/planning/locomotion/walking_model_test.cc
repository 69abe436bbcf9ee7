#include "cairn/planning/locomotion/walking_model.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "expect_throws.h"
#include "test_paths.h"

namespace cairn::planning {
namespace {

const std::string kYaml = std::string(CAIRN_SOURCE_DIR) + "/data/robots/cairn_humanoid_walking.yaml";

std::string ReadText(const std::string& path) {
  std::ifstream in(path);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

// Writes the shipped YAML with `from` replaced by `to` into a temporary folder next to a copy of the URDF.
std::string WriteVariant(const std::string& from, const std::string& to) {
  const std::filesystem::path folder = std::filesystem::temp_directory_path() / "cairn_walking_model_test";
  std::filesystem::create_directories(folder);
  std::filesystem::copy_file(std::string(CAIRN_SOURCE_DIR) + "/data/robots/cairn_humanoid.urdf",
                             folder / "cairn_humanoid.urdf", std::filesystem::copy_options::overwrite_existing);
  std::string text = ReadText(kYaml);
  const std::size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) text.replace(at, from.size(), to);
  const std::string path = (folder / "walking.yaml").string();
  std::ofstream(path) << text;
  return path;
}

TEST(WalkingModelTest, LoadsTheHumanoid) {
  const WalkingModel model = WalkingModel::Load(kYaml);
  EXPECT_EQ(model.name(), "cairn_humanoid");
  EXPECT_NEAR(model.mass(), 64.0, 1e-9);
  EXPECT_NEAR(model.gravity(), 9.81, 1e-12);
  EXPECT_DOUBLE_EQ(model.foot_length(), 0.24);
  EXPECT_DOUBLE_EQ(model.foot_width(), 0.14);
  EXPECT_DOUBLE_EQ(model.reach().dx_max, 0.38);
  EXPECT_DOUBLE_EQ(model.reach().dy_min, 0.17);
  EXPECT_NEAR(model.reach().dtheta_max, 30.0 * M_PI / 180.0, 1e-15);
  EXPECT_DOUBLE_EQ(model.parameter_lower().t_ds, 0.09);
  EXPECT_DOUBLE_EQ(model.parameter_upper().t_sw, 1.8);

  // Leg geometry from the URDF (data/robots/README.md: thigh and shank 0.33 m, ankle 0.10 m above the sole,
  // sole centre 0.03 m ahead of the ankle, hips 0.16 m apart).
  const LegGeometry& leg = model.leg();
  EXPECT_NEAR(leg.thigh_length, 0.33, 1e-12);
  EXPECT_NEAR(leg.shank_length, 0.33, 1e-12);
  EXPECT_NEAR(leg.ankle_height, 0.10, 1e-12);
  EXPECT_NEAR(leg.ankle_forward, -0.03, 1e-12);
  EXPECT_NEAR(leg.hip_from_com.y(), 0.08, 1e-12);
  EXPECT_NEAR(leg.leg_length_max, 0.66 * std::cos(0.5 * M_PI / 180.0), 1e-12);
  EXPECT_NEAR(leg.leg_length_min, 0.66 * std::cos(45.0 * M_PI / 180.0), 1e-12);
  // COM above the soles at the zero configuration = hip height 0.76 m plus the COM's offset above the hips.
  EXPECT_NEAR(leg.com_height_standing, 0.76 - leg.hip_from_com.z(), 1e-12);
  EXPECT_LE(model.parameter_upper().com_height, 0.10 + leg.leg_length_max - leg.hip_from_com.z() + 1e-12);
  EXPECT_GE(model.parameter_lower().com_height, 0.10 + leg.leg_length_min - leg.hip_from_com.z() - 1e-12);

  // Body box: from the knees (0.43 m) to the 1.50 m head top lowered by the 0.20 m crouch.
  EXPECT_NEAR(model.body_box_bottom(), 0.43, 1e-12);
  EXPECT_NEAR(model.body_half_extents().z(), 0.5 * (1.30 - 0.43), 1e-9);
  EXPECT_GT(model.body_half_extents().x(), 0.1);
  EXPECT_GT(model.body_half_extents().y(), 0.2);

  EXPECT_DOUBLE_EQ(model.motor(3).resistance, 0.299);
  EXPECT_DOUBLE_EQ(model.motor(3).torque_constant, 0.0302);
  EXPECT_DOUBLE_EQ(model.motor(3).gear_ratio, 200.0);
  EXPECT_THROW(model.motor(6), std::out_of_range);
  EXPECT_EQ(model.left_leg_joint_names()[3], "l_knee");
  EXPECT_LT(model.leg_torques().max_ik_residual(), 1e-9);
}

TEST(WalkingModelTest, HashFollowsTheFileContents) {
  const WalkingModel a = WalkingModel::Load(kYaml);
  const WalkingModel b = WalkingModel::Load(WriteVariant("swing_height: 0.05", "swing_height: 0.05  # same"));
  const WalkingModel c = WalkingModel::Load(WriteVariant("swing_height: 0.05", "swing_height: 0.06"));
  EXPECT_NE(a.content_hash(), 0u);
  EXPECT_NE(b.content_hash(), c.content_hash());
  EXPECT_EQ(WalkingModel::Load(kYaml).content_hash(), a.content_hash());
}

TEST(WalkingModelTest, LegTorquesObeyStatics) {
  const WalkingModel model = WalkingModel::Load(kYaml);
  const LegTorqueTable& table = model.leg_torques();
  const double f = model.mass() * model.gravity();
  Eigen::Matrix<double, 6, 1> tau0, tau1;
  // A vertical force cannot twist a vertical hip-yaw axis, whatever the posture and centre of pressure.
  for (const Eigen::Vector3d& e : {Eigen::Vector3d(0.1, 0.02, -0.6), Eigen::Vector3d(-0.15, -0.05, -0.58)}) {
    table.Torques(e, f, Eigen::Vector2d(0.05, -0.02), tau0);
    EXPECT_NEAR(tau0[0], 0.0, 1e-9);
  }
  // Leg straight down at a grid node (pitch 0, roll 0): the ankle-pitch axis is horizontal through the ankle,
  // so moving the centre of pressure forward by 0.1 m changes its torque by exactly f * 0.1.
  const LegTorqueGrid& grid = table.grid();
  ASSERT_EQ(grid.pitch_min, -grid.pitch_max);
  const Eigen::Vector3d straight(0.0, 0.0, -grid.length_max);
  const double under_ankle = model.leg().ankle_forward;  // centre of pressure below the ankle axis
  table.Torques(straight, f, Eigen::Vector2d(under_ankle, 0.0), tau0);
  table.Torques(straight, f, Eigen::Vector2d(under_ankle + 0.1, 0.0), tau1);
  EXPECT_NEAR(std::abs(tau1[4] - tau0[4]), 0.1 * f, 1e-6 * f);
  // Weight straight up a nearly straight leg (1 degree of knee flexion): the ankle holds only the foot, and
  // the knee only the shank and foot plus the 3 mm lever of the bend.
  EXPECT_LT(std::abs(tau0[4]), 5.0);
  EXPECT_LT(std::abs(tau0[3]), 5.0);
  // Moving the load 0.1 m forward loads the knee with about the same moment (the knee is above the ankle).
  EXPECT_NEAR(std::abs(tau1[3] - tau0[3]), 0.1 * f, 0.01 * f);
}

TEST(WalkingModelTest, ErrorsNameTheFileAndKey) {
  CAIRN_EXPECT_THROWS_WITH(WalkingModel::Load("/nonexistent/walking.yaml"), std::invalid_argument,
                           "Cannot read '/nonexistent/walking.yaml'");
  CAIRN_EXPECT_THROWS_WITH(WalkingModel::Load(WriteVariant("reach:", "reech:")), std::invalid_argument, "walking.yaml",
                           "unknown key 'reech'", "Did you mean 'reach'?");
  CAIRN_EXPECT_THROWS_WITH(WalkingModel::Load(WriteVariant("t_ds: [0.09, 1.8]", "t_ds: [0.09, fast]")),
                           std::invalid_argument, "In '", "line", "'parameters.t_ds' must be a number, got 'fast'");
  CAIRN_EXPECT_THROWS_WITH(WalkingModel::Load(WriteVariant("t_sw: [0.9, 1.8]", "t_sw: [1.8, 0.9]")),
                           std::invalid_argument, "parameters.t_sw", "above max");
  CAIRN_EXPECT_THROWS_WITH(WalkingModel::Load(WriteVariant("com_height: [0.61, 0.79]", "com_height: [0.50, 0.79]")),
                           std::invalid_argument, "parameters.com_height", "not reachable", "0.606");
  CAIRN_EXPECT_THROWS_WITH(WalkingModel::Load(WriteVariant("  dy: [0.17, 0.30]", "  dy: [0.10, 0.30]")),
                           std::invalid_argument, "reach.dy", "sole width");
  CAIRN_EXPECT_THROWS_WITH(WalkingModel::Load(WriteVariant("urdf: cairn_humanoid.urdf", "urdf: missing.urdf")),
                           std::invalid_argument, "key 'urdf'", "does not exist");
  CAIRN_EXPECT_THROWS_WITH(WalkingModel::Load(WriteVariant("resistance: 0.299", "resistance: -1")),
                           std::invalid_argument, "motors.hip_yaw.resistance", "outside its valid range");
  CAIRN_EXPECT_THROWS_WITH(WalkingModel::Load(WriteVariant("l_knee,", "l_kne,")), std::invalid_argument,
                           "left_leg_joints", "'l_kne'", "l_knee");
  CAIRN_EXPECT_THROWS_WITH(WalkingModel::Load(WriteVariant("swing_height: 0.05", "swing_height: [0.05")),
                           std::invalid_argument, "Malformed YAML in");
  CAIRN_EXPECT_THROWS_WITH(WalkingModel::Load(WriteVariant("  crouch: 0.20", "")), std::invalid_argument,
                           "body_box");
  CAIRN_EXPECT_THROWS_WITH(WalkingModel::Load(WriteVariant("swing_height: 0.05", "swing_height: 0.05\nname: twice")),
                           std::invalid_argument, "the key 'name' appears twice");
  // The name becomes a cache file's name: no folders, no line breaks.
  CAIRN_EXPECT_THROWS_WITH(WalkingModel::Load(WriteVariant("name: cairn_humanoid", "name: ../../etc/robot")),
                           std::invalid_argument, "key 'name'", "letters, digits", "'../../etc/robot'");
  CAIRN_EXPECT_THROWS_WITH(WalkingModel::Load(WriteVariant("resistance: 0.299", "resistance: .nan")),
                           std::invalid_argument, "motors.hip_yaw.resistance", "finite");
}

}  // namespace
}  // namespace cairn::planning
