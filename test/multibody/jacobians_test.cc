#include <cairn/multibody/jacobians.h>

#include <random>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cairn/multibody/center_of_mass.h>
#include <cairn/multibody/configuration.h>
#include <cairn/multibody/kinematics.h>

#include "expect_throws.h"
#include "test_models.h"

namespace cairn::multibody {
namespace {

Eigen::Vector3d RotationVector(const Eigen::Matrix3d& R) {
  const Eigen::AngleAxisd aa(R);
  return aa.angle() * aa.axis();
}

class JacobiansTest : public ::testing::TestWithParam<std::string> {};

// Every frame's Jacobian, in all three reference frames, against central differences along each tangent
// direction.
TEST_P(JacobiansTest, FrameJacobiansMatchFiniteDifferences) {
  const Model model = test::LoadRobot(GetParam(), true);
  Data data(model);
  std::mt19937 rng(11);
  const Eigen::VectorXd q = RandomConfiguration(model, rng, 1.0);
  const int nv = model.nv();
  const double h = 1e-6;
  std::vector<Pose> plus(static_cast<std::size_t>(model.num_frames() * nv));
  std::vector<Pose> minus(plus.size());
  for (int k = 0; k < nv; ++k) {
    const Eigen::VectorXd e = Eigen::VectorXd::Unit(nv, k);
    ForwardKinematics(model, data, Integrate(model, q, e, h));
    for (int f = 0; f < model.num_frames(); ++f) plus[static_cast<std::size_t>(f * nv + k)] = FramePose(model, data, f);
    ForwardKinematics(model, data, Integrate(model, q, e, -h));
    for (int f = 0; f < model.num_frames(); ++f)
      minus[static_cast<std::size_t>(f * nv + k)] = FramePose(model, data, f);
  }
  ForwardKinematics(model, data, q);
  Eigen::MatrixXd J_aligned(6, nv), J_local(6, nv), J_world(6, nv);
  for (int f = 0; f < model.num_frames(); ++f) {
    FrameJacobian(model, data, f, ReferenceFrame::kWorldAligned, J_aligned);
    FrameJacobian(model, data, f, ReferenceFrame::kLocal, J_local);
    FrameJacobian(model, data, f, ReferenceFrame::kWorld, J_world);
    const Pose X = FramePose(model, data, f);
    for (int k = 0; k < nv; ++k) {
      const Pose& P = plus[static_cast<std::size_t>(f * nv + k)];
      const Pose& M = minus[static_cast<std::size_t>(f * nv + k)];
      Vector6d numeric;
      numeric.head<3>() = RotationVector(P.rotation() * M.rotation().transpose()) / (2 * h);
      numeric.tail<3>() = (P.translation() - M.translation()) / (2 * h);
      EXPECT_LT((J_aligned.col(k) - numeric).cwiseAbs().maxCoeff(), 1e-7) << model.frame(f).name << " col " << k;
      Vector6d local;
      local.head<3>() = X.rotation().transpose() * J_aligned.col(k).head<3>();
      local.tail<3>() = X.rotation().transpose() * J_aligned.col(k).tail<3>();
      EXPECT_LT((J_local.col(k) - local).cwiseAbs().maxCoeff(), 1e-12);
      const Eigen::Vector3d w = J_world.col(k).head<3>();
      EXPECT_LT((J_world.col(k).tail<3>() + w.cross(X.translation()) - J_aligned.col(k).tail<3>()).norm(), 1e-12);
    }
  }
}

TEST_P(JacobiansTest, JacobianTimesVelocityIsTheFrameTwist) {
  const Model model = test::LoadRobot(GetParam(), true);
  Data data(model);
  std::mt19937 rng(12);
  std::normal_distribution<double> normal(0.0, 1.0);
  const Eigen::VectorXd q = RandomConfiguration(model, rng, 1.0);
  Eigen::VectorXd v(model.nv());
  for (int i = 0; i < v.size(); ++i) v[i] = normal(rng);
  ForwardKinematics(model, data, q, v);
  Eigen::MatrixXd J(6, model.nv());
  for (int f = 0; f < model.num_frames(); ++f) {
    FrameJacobian(model, data, f, ReferenceFrame::kLocal, J);
    EXPECT_LT((J * v - FrameVelocity(model, data, f)).cwiseAbs().maxCoeff(), 1e-10) << model.frame(f).name;
  }
}

TEST_P(JacobiansTest, PathOnlyJacobianEqualsTheFullOne) {
  const Model model = test::LoadRobot(GetParam(), true);
  Data full(model), path(model);
  std::mt19937 rng(14);
  const Eigen::VectorXd q = RandomConfiguration(model, rng, 1.0);
  ForwardKinematics(model, full, q);
  Eigen::MatrixXd expected(6, model.nv()), actual(6, model.nv());
  for (int f = 0; f < model.num_frames(); ++f) {
    FrameJacobian(model, full, f, ReferenceFrame::kWorldAligned, expected);
    FrameJacobian(model, path, q, f, ReferenceFrame::kWorldAligned, actual);
    EXPECT_EQ(expected, actual) << model.frame(f).name;
  }
}

TEST_P(JacobiansTest, CenterOfMassJacobianMatchesFiniteDifferences) {
  const Model model = test::LoadRobot(GetParam(), true);
  Data data(model);
  std::mt19937 rng(13);
  const Eigen::VectorXd q = RandomConfiguration(model, rng, 1.0);
  const Eigen::Matrix3Xd J = CenterOfMassJacobian(model, data, q);
  const double h = 1e-6;
  for (int k = 0; k < model.nv(); ++k) {
    const Eigen::VectorXd e = Eigen::VectorXd::Unit(model.nv(), k);
    const Eigen::Vector3d plus = CenterOfMass(model, data, Integrate(model, q, e, h));
    const Eigen::Vector3d minus = CenterOfMass(model, data, Integrate(model, q, e, -h));
    EXPECT_LT((J.col(k) - (plus - minus) / (2 * h)).cwiseAbs().maxCoeff(), 1e-8) << k;
  }
  // The centre of mass is the mass-weighted mean of the bodies' centres.
  const Eigen::Vector3d com = CenterOfMass(model, data, q);
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  for (int i = 1; i < model.num_bodies(); ++i) {
    const SpatialInertia& I = model.body(i).inertia;
    sum += I.mass() * (data.X_world[static_cast<std::size_t>(i)] * I.com());
  }
  EXPECT_LT((com - sum / model.total_mass()).norm(), 1e-12);
}

INSTANTIATE_TEST_SUITE_P(Robots, JacobiansTest,
                         ::testing::Values(test::AtlasUrdf(), test::DrcHuboUrdf(), test::HumanoidUrdf()),
                         [](const auto& info) { return test::RobotName(info.param); });

TEST(JacobiansErrorsTest, WrongSizeAndFrameAreReported) {
  const Model model = test::LoadRobot(test::AtlasUrdf(), false);
  Data data(model);
  ForwardKinematics(model, data, Eigen::VectorXd::Zero(model.nq()));
  Eigen::MatrixXd J(6, 3);
  CAIRN_EXPECT_THROWS_WITH(FrameJacobian(model, data, 0, ReferenceFrame::kLocal, J), std::invalid_argument, "6 x 3",
                           "6 x 27");
  Eigen::MatrixXd ok(6, model.nv());
  CAIRN_EXPECT_THROWS_WITH(FrameJacobian(model, data, 999, ReferenceFrame::kLocal, ok), std::invalid_argument,
                           "frame index 999", "GetFrameIndex");
  const Model other = test::LoadRobot(test::AtlasUrdf(), true);
  CAIRN_EXPECT_THROWS_WITH(ForwardKinematics(other, data, Eigen::VectorXd::Zero(other.nq())), std::invalid_argument,
                           "Data(model)");
}

}  // namespace
}  // namespace cairn::multibody
