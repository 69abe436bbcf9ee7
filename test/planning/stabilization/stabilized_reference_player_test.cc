// StabilizedReferencePlayer: interpolation between control samples, held ends, and the errors of an unusable
// reference.
#include <gtest/gtest.h>

#include <cmath>

#include <Eigen/Geometry>

#include <cairn/multibody/configuration.h>
#include <cairn/planning/stabilization/stabilized_reference_player.h>

#include "../trajectory/test_robot.h"
#include "expect_throws.h"

namespace cairn::planning {
namespace {

// Three samples 0.1 s apart: the base moves 0.1 m per sample and turns 90 degrees about z between the first and
// the last, one joint coordinate ramps.
StabilizedTrajectory ThreeSamples(const multibody::Model& model) {
  StabilizedTrajectory reference;
  reference.period = 0.1;
  for (int k = 0; k < 3; ++k) {
    Eigen::VectorXd q = multibody::NeutralConfiguration(model);
    q[0] = 0.1 * k;
    q[2] = 0.9;
    const Eigen::Quaterniond r(Eigen::AngleAxisd(M_PI / 4.0 * k, Eigen::Vector3d::UnitZ()));
    q.segment<4>(3) << r.w(), r.x(), r.y(), r.z();
    q[7] = 0.2 * k;
    Eigen::VectorXd v = Eigen::VectorXd::Zero(model.nv());
    v[6] = 2.0;  // the first joint's rate: 0.2 rad per 0.1 s
    reference.q.push_back(q);
    reference.v.push_back(v);
  }
  reference.report.success = true;
  return reference;
}

TEST(StabilizedReferencePlayerTest, InterpolatesBetweenSamplesAndTheQuaternionOnTheSphere) {
  const auto model = test::Humanoid();
  const StabilizedReferencePlayer player(model);
  auto context = player.CreateDefaultContext();
  player.get_reference_input_port().FixValue(context.get(), ThreeSamples(*model));
  const int nq = model->nq();
  context->SetTime(0.125);
  const Eigen::VectorXd& y = player.get_reference_output_port().Eval<Eigen::VectorXd>(*context);
  ASSERT_EQ(y.size(), nq + model->nv());
  EXPECT_NEAR(y[0], 0.125, 1e-12);
  EXPECT_NEAR(y[7], 0.25, 1e-12);
  const Eigen::Quaterniond r(y[3], y[4], y[5], y[6]);
  EXPECT_NEAR(r.norm(), 1.0, 1e-12);  // a linear blend of the coefficients would be shorter
  const Eigen::AngleAxisd turn(r);
  EXPECT_NEAR(turn.angle(), M_PI / 4.0 * 1.25, 1e-9);
  EXPECT_NEAR(y[nq + 6], 2.0, 1e-12);
}

TEST(StabilizedReferencePlayerTest, HoldsTheFirstSampleBeforeAndTheLastAtRestAfter) {
  const auto model = test::Humanoid();
  const StabilizedReferencePlayer player(model);
  const StabilizedTrajectory reference = ThreeSamples(*model);
  const Eigen::VectorXd start = player.Sample(reference, 0.0);
  EXPECT_EQ(start.head(model->nq()), reference.q[0]);
  EXPECT_EQ(start.tail(model->nv()), reference.v[0]);
  const Eigen::VectorXd end = player.Sample(reference, 5.0);
  EXPECT_EQ(end.head(model->nq()), reference.q[2]);
  EXPECT_TRUE(end.tail(model->nv()).isZero());
  // Exactly at a sample the sample itself comes out.
  EXPECT_TRUE(player.Sample(reference, 0.1).head(model->nq()).isApprox(reference.q[1], 1e-12));
}

TEST(StabilizedReferencePlayerTest, FollowsTheContextTimeThroughTheCache) {
  const auto model = test::Humanoid();
  const StabilizedReferencePlayer player(model);
  auto context = player.CreateDefaultContext();
  player.get_reference_input_port().FixValue(context.get(), ThreeSamples(*model));
  context->SetTime(0.05);
  const double early = player.get_reference_output_port().Eval<Eigen::VectorXd>(*context)[0];
  context->SetTime(0.15);
  const double late = player.get_reference_output_port().Eval<Eigen::VectorXd>(*context)[0];
  EXPECT_NEAR(early, 0.05, 1e-12);
  EXPECT_NEAR(late, 0.15, 1e-12);
}

TEST(StabilizedReferencePlayerTest, AnEmptyOrMisshapenReferenceIsAnErrorThatSaysWhy) {
  const auto model = test::Humanoid();
  const StabilizedReferencePlayer player(model);
  StabilizedTrajectory empty;
  empty.report.message = "no trajectory to stabilise: not solved yet";
  CAIRN_EXPECT_THROWS_WITH(player.Sample(empty, 0.0), std::runtime_error,
                           "the stabilised reference is empty (no trajectory to stabilise: not solved yet)");
  StabilizedTrajectory short_q = ThreeSamples(*model);
  short_q.q[1].conservativeResize(5);
  CAIRN_EXPECT_THROWS_WITH(player.Sample(short_q, 0.15), std::invalid_argument, "sample 1 has q of size 5");
  CAIRN_EXPECT_THROWS_WITH(player.Sample(ThreeSamples(*model), NAN), std::invalid_argument, "is not finite");
  CAIRN_EXPECT_THROWS_WITH(StabilizedReferencePlayer(nullptr), std::invalid_argument, "the robot model is null");
}

}  // namespace
}  // namespace cairn::planning
