// The project's humanoid (data/robots/cairn_humanoid.urdf): size, mass, frames, symmetry and geometry kinds.

#include <gtest/gtest.h>

#include <cairn/multibody/center_of_mass.h>
#include <cairn/multibody/configuration.h>
#include <cairn/multibody/gravity_torques.h>
#include <cairn/multibody/kinematics.h>

#include "test_models.h"

namespace cairn::multibody {
namespace {

class HumanoidTest : public ::testing::Test {
 protected:
  HumanoidTest() : model_(test::LoadRobot(test::HumanoidUrdf(), true)), data_(model_) {
    q_ = NeutralConfiguration(model_);
    q_[model_.joint(model_.GetJointIndex("root_joint")).idx_q + 2] = 0.86;  // pelvis height when standing
  }
  Model model_;
  Data data_;
  Eigen::VectorXd q_;
};

TEST_F(HumanoidTest, IsWabian2Sized) {
  EXPECT_EQ(model_.nv(), 6 + 30);
  EXPECT_EQ(model_.nq(), 7 + 30);
  EXPECT_NEAR(model_.total_mass(), 64.0, 1e-12);
  ForwardKinematics(model_, data_, q_);
  // Standing straight, both soles on the ground.
  for (const char* sole : {"l_sole", "r_sole"}) {
    EXPECT_NEAR(FramePose(model_, data_, model_.GetFrameIndex(sole)).translation().z(), 0.0, 1e-12) << sole;
  }
  const Eigen::Vector3d head = data_.X_world[static_cast<std::size_t>(model_.GetBodyIndex("head"))].translation();
  const Geometry& skull = model_.body(model_.GetBodyIndex("head")).collisions.at(0);
  EXPECT_NEAR(head.z() + skull.X_BG.translation().z() + skull.radius, 1.50, 1e-9);
  const Eigen::Vector3d com = CenterOfMass(model_, data_, q_);
  EXPECT_NEAR(com.y(), 0.0, 1e-12);
  EXPECT_GT(com.z(), 0.7);
  EXPECT_LT(com.z(), 1.0);
}

TEST_F(HumanoidTest, LeftAndRightAreMirrorImages) {
  std::mt19937 rng(41);
  Eigen::VectorXd q = RandomConfiguration(model_, rng, 1.0);
  const Joint& root = model_.joint(model_.GetJointIndex("root_joint"));
  q.segment<7>(root.idx_q) << 0, 0, 0.86, 1, 0, 0, 0;
  // Same numeric angles on both sides (the right roll/yaw axes are flipped) make a mirrored posture.
  for (int j = 1; j < model_.num_bodies(); ++j) {
    const std::string& name = model_.joint(j).name;
    if (name.rfind("l_", 0) == 0 && model_.joint(j).nq == 1) {
      q[model_.joint(model_.GetJointIndex("r_" + name.substr(2))).idx_q] = q[model_.joint(j).idx_q];
    }
  }
  for (const char* centre : {"waist_yaw", "waist_roll", "neck_yaw"})
    q[model_.joint(model_.GetJointIndex(centre)).idx_q] = 0.0;
  ForwardKinematics(model_, data_, q);
  for (int b = 1; b < model_.num_bodies(); ++b) {
    const std::string& name = model_.body(b).name;
    if (name.rfind("l_", 0) != 0) continue;
    const Eigen::Vector3d left = data_.X_world[static_cast<std::size_t>(b)].translation();
    const Eigen::Vector3d right =
        data_.X_world[static_cast<std::size_t>(model_.GetBodyIndex("r_" + name.substr(2)))].translation();
    EXPECT_LT((left - Eigen::Vector3d(right.x(), -right.y(), right.z())).norm(), 1e-12) << name;
  }
}

TEST_F(HumanoidTest, CollisionGeometryIsPrimitivesOnly) {
  int capsules = 0;
  for (const Body& body : model_.bodies()) {
    for (const Geometry& g : body.collisions) {
      EXPECT_TRUE(g.type == GeometryType::kBox || g.type == GeometryType::kSphere || g.type == GeometryType::kCapsule)
          << body.name << " " << GeometryTypeName(g.type);
      capsules += g.type == GeometryType::kCapsule ? 1 : 0;
    }
  }
  EXPECT_EQ(capsules, 8);
  for (const char* frame : {"l_sole", "r_sole", "l_palm", "r_palm", "head_camera"}) EXPECT_TRUE(model_.HasFrame(frame));
}

TEST_F(HumanoidTest, StandingGravityTorquesAreSmallAndSymmetric) {
  const Eigen::VectorXd g = GravityTorques(model_, data_, q_);
  // Straight legs: the hip roll axes see no moment; knees and ankles only hold the feet, whose centres of mass
  // are 3 cm ahead of the ankle axes.
  auto torque = [&](const char* joint) { return g[model_.joint(model_.GetJointIndex(joint)).idx_v]; };
  for (const char* side : {"l_", "r_"}) {
    const std::string s(side);
    EXPECT_NEAR(torque((s + "hip_roll").c_str()), 0.0, 1e-9);
    EXPECT_NEAR(torque((s + "knee").c_str()), -1.6 * 9.81 * 0.03, 1e-9);
    EXPECT_NEAR(torque((s + "ankle_pitch").c_str()), -1.6 * 9.81 * 0.03, 1e-9);
  }
  EXPECT_NEAR(torque("l_hip_pitch"), torque("r_hip_pitch"), 1e-12);
  // The floating base must hold the full weight.
  const Joint& root = model_.joint(model_.GetJointIndex("root_joint"));
  EXPECT_NEAR(g[root.idx_v + 5], 64.0 * 9.81, 1e-9);
}

}  // namespace
}  // namespace cairn::multibody
