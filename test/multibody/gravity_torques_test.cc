#include <cairn/multibody/gravity_torques.h>

#include <random>

#include <gtest/gtest.h>

#include <cairn/multibody/configuration.h>
#include <cairn/multibody/dynamics.h>
#include <cairn/multibody/jacobians.h>
#include <cairn/multibody/kinematics.h>

#include "test_models.h"

namespace cairn::multibody {
namespace {

class GravityTorquesTest : public ::testing::TestWithParam<std::tuple<std::string, bool>> {};

TEST_P(GravityTorquesTest, EqualInverseDynamicsAtRestAndTheThesisSum) {
  const Model model = test::LoadRobot(std::get<0>(GetParam()), std::get<1>(GetParam()));
  Data data(model);
  std::mt19937 rng(21);
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(model.nv());
  for (int trial = 0; trial < 3; ++trial) {
    const Eigen::VectorXd q = RandomConfiguration(model, rng, 1.0);
    const Eigen::VectorXd g = GravityTorques(model, data, q);
    EXPECT_LT((g - InverseDynamics(model, data, q, zero, zero)).cwiseAbs().maxCoeff(), 1e-9);
    // Thesis eq. 2.11: tau = sum_i J_i^T F_gi, J_i the Jacobian of link i's centre of mass, F_gi = -m_i g.
    ForwardKinematics(model, data, q);
    Eigen::VectorXd thesis = Eigen::VectorXd::Zero(model.nv());
    Eigen::MatrixXd J(6, model.nv());
    for (int i = 1; i < model.num_bodies(); ++i) {
      const SpatialInertia& I = model.body(i).inertia;
      if (I.mass() == 0.0) continue;
      FrameJacobian(model, data, model.GetFrameIndex(model.body(i).name), ReferenceFrame::kWorld, J);
      const Eigen::Vector3d c = data.X_world[static_cast<std::size_t>(i)] * I.com();
      Eigen::MatrixXd J_point = J.bottomRows<3>();
      for (int k = 0; k < model.nv(); ++k) J_point.col(k) += J.col(k).head<3>().cross(c);
      thesis += J_point.transpose() * (-I.mass() * model.gravity());
    }
    EXPECT_LT((g - thesis).cwiseAbs().maxCoeff(), 1e-9);
  }
}

TEST_P(GravityTorquesTest, DerivativeMatchesFiniteDifferences) {
  const Model model = test::LoadRobot(std::get<0>(GetParam()), std::get<1>(GetParam()));
  Data data(model);
  std::mt19937 rng(22);
  const Eigen::VectorXd q = RandomConfiguration(model, rng, 1.0);
  const Eigen::MatrixXd D = GravityTorquesDerivative(model, data, q);
  EXPECT_LT((data.gravity_torques - GravityTorques(model, data, q)).norm(), 1e-12);
  const double h = 1e-6;
  for (int k = 0; k < model.nv(); ++k) {
    const Eigen::VectorXd e = Eigen::VectorXd::Unit(model.nv(), k);
    const Eigen::VectorXd plus = GravityTorques(model, data, Integrate(model, q, e, h));
    const Eigen::VectorXd minus = GravityTorques(model, data, Integrate(model, q, e, -h));
    const Eigen::VectorXd numeric = (plus - minus) / (2 * h);
    EXPECT_LT((D.col(k) - numeric).cwiseAbs().maxCoeff(), 1e-6 * std::max(1.0, numeric.cwiseAbs().maxCoeff()))
        << "column " << k;
  }
}

INSTANTIATE_TEST_SUITE_P(
    Robots, GravityTorquesTest,
    ::testing::Values(std::make_tuple(test::AtlasUrdf(), true), std::make_tuple(test::AtlasUrdf(), false),
                      std::make_tuple(test::DrcHuboUrdf(), true), std::make_tuple(test::HumanoidUrdf(), true)),
    [](const auto& info) {
      return test::RobotName(std::get<0>(info.param)) + (std::get<1>(info.param) ? "Floating" : "Fixed");
    });

}  // namespace
}  // namespace cairn::multibody
