// GravityFeedforward: the static gravity torques of every joint that carries no loaded sole, none on a stance leg's
// chain or the base; a system whose output is its Torques; one-line errors.
#include <memory>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include <cairn/multibody/configuration.h>
#include <cairn/multibody/data.h>
#include <cairn/multibody/gravity_torques.h>
#include <cairn/multibody/plant/sole_state.h>
#include <cairn/planning/walk/gravity_feedforward.h>
#include <cairn/systems/framework/value.h>

#include "../trajectory/test_robot.h"
#include "expect_throws.h"

namespace cairn::planning {
namespace {

// The humanoid with its knees and arms bent, so that every joint carries some gravity torque.
Eigen::VectorXd Bent(const multibody::Model& model) {
  Eigen::VectorXd q = multibody::NeutralConfiguration(model);
  q[2] = 0.75;
  for (const char* joint : {"l_knee", "r_knee"}) q[model.joint(model.GetJointIndex(joint)).idx_q] = 0.6;
  for (const char* joint : {"l_hip_pitch", "r_hip_pitch"}) q[model.joint(model.GetJointIndex(joint)).idx_q] = -0.3;
  for (const char* joint : {"l_shoulder_pitch", "r_shoulder_pitch"}) {
    q[model.joint(model.GetJointIndex(joint)).idx_q] = -0.8;
  }
  return q;
}

int V(const multibody::Model& model, const char* joint) { return model.joint(model.GetJointIndex(joint)).idx_v; }

TEST(GravityFeedforwardTest, HoldsEveryJointThatCarriesNoLoadedSole) {
  const auto model = test::Humanoid();
  const GravityFeedforward feedforward(model, {"l_sole", "r_sole"});
  const Eigen::VectorXd q = Bent(*model);
  multibody::Data data(*model);
  const Eigen::VectorXd g = multibody::GravityTorques(*model, data, q);

  // In the air every joint is held; the base is not actuated.
  const Eigen::VectorXd air = feedforward.Torques(q, false, false);
  EXPECT_EQ(air.head(6).norm(), 0.0);
  EXPECT_TRUE(air.tail(model->nv() - 6).isApprox(g.tail(model->nv() - 6), 1e-12));

  // Standing on the left: the left leg's joints get nothing, the swinging right leg and the arms their g(q).
  const Eigen::VectorXd left = feedforward.Torques(q, true, false);
  for (const char* joint : {"l_hip_yaw", "l_hip_roll", "l_hip_pitch", "l_knee", "l_ankle_pitch", "l_ankle_roll"}) {
    EXPECT_EQ(left[V(*model, joint)], 0.0) << joint;
  }
  for (const char* joint : {"r_hip_pitch", "r_knee", "r_ankle_pitch", "l_shoulder_pitch"}) {
    EXPECT_EQ(left[V(*model, joint)], g[V(*model, joint)]) << joint;
    EXPECT_NE(left[V(*model, joint)], 0.0) << joint;
  }
  // On both feet only the upper body is held.
  const Eigen::VectorXd both = feedforward.Torques(q, true, true);
  EXPECT_EQ(both[V(*model, "r_knee")], 0.0);
  EXPECT_EQ(both[V(*model, "r_shoulder_pitch")], g[V(*model, "r_shoulder_pitch")]);

  // The gain scales it.
  const GravityFeedforward half(model, {"l_sole", "r_sole"}, 0.5);
  EXPECT_TRUE(half.Torques(q, true, false).isApprox(0.5 * left, 1e-12));
}

TEST(GravityFeedforwardTest, TheOutputIsTheTorquesOfItsInputs) {
  const auto model = test::Humanoid();
  const GravityFeedforward feedforward(model, {"l_sole", "r_sole"});
  auto context = feedforward.CreateDefaultContext();
  Eigen::VectorXd state = Eigen::VectorXd::Zero(model->nq() + model->nv());
  state.head(model->nq()) = Bent(*model);
  feedforward.get_state_input_port().FixValue(context.get(), state);
  std::vector<multibody::SoleState> soles(2);
  soles[1].loaded = true;
  feedforward.get_contacts_input_port().FixValue(context.get(), soles);
  EXPECT_EQ(feedforward.get_torque_output_port().Eval<Eigen::VectorXd>(*context),
            feedforward.Torques(state.head(model->nq()), false, true));
}

TEST(GravityFeedforwardTest, RefusesBadModelsSolesGainsAndSizes) {
  const auto model = test::Humanoid();
  CAIRN_EXPECT_THROWS_WITH(GravityFeedforward(nullptr, {"l_sole", "r_sole"}), std::invalid_argument,
                           "the robot model is null");
  CAIRN_EXPECT_THROWS_WITH(GravityFeedforward(model, {"l_sole", "r_foot_plate"}), std::invalid_argument,
                           "no body or frame 'r_foot_plate'", "name the sole bodies");
  CAIRN_EXPECT_THROWS_WITH(GravityFeedforward(model, {"l_sole"}), std::invalid_argument, "1 sole bodies given");
  CAIRN_EXPECT_THROWS_WITH(GravityFeedforward(model, {"l_sole", "r_sole"}, 1.5), std::invalid_argument,
                           "gain 1.5 must be in [0, 1]");
  const GravityFeedforward feedforward(model, {"l_sole", "r_sole"});
  CAIRN_EXPECT_THROWS_WITH(feedforward.Torques(Eigen::VectorXd::Zero(3), true, true), std::invalid_argument,
                           "q has 3 entries");
}

}  // namespace
}  // namespace cairn::planning
