#include <cairn/multibody/dynamics.h>

#include <random>

#include <Eigen/Eigenvalues>
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cairn/multibody/center_of_mass.h>
#include <cairn/multibody/configuration.h>
#include <cairn/multibody/gravity_torques.h>
#include <cairn/multibody/kinematics.h>
#include <cairn/multibody/model_builder.h>

#include "expect_throws.h"
#include "test_models.h"

namespace cairn::multibody {
namespace {

Eigen::VectorXd RandomVector(int n, std::mt19937& rng) {
  std::normal_distribution<double> normal(0.0, 1.0);
  Eigen::VectorXd x(n);
  for (int i = 0; i < n; ++i) x[i] = normal(rng);
  return x;
}

class DynamicsTest : public ::testing::TestWithParam<std::string> {};

TEST_P(DynamicsTest, MassMatrixInverseDynamicsAndForwardDynamicsAreConsistent) {
  const Model model = test::LoadRobot(GetParam(), true);
  Data data(model);
  std::mt19937 rng(31);
  const int nv = model.nv();
  const Eigen::VectorXd q = RandomConfiguration(model, rng, 1.0);
  const Eigen::VectorXd v = RandomVector(nv, rng);
  const Eigen::VectorXd a = RandomVector(nv, rng);
  const Eigen::MatrixXd M = MassMatrix(model, data, q);
  EXPECT_LT((M - M.transpose()).cwiseAbs().maxCoeff(), 1e-12);
  EXPECT_GT(Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(M).eigenvalues().minCoeff(), 0.0);
  // RNEA is affine in a with slope M.
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(nv);
  const Eigen::VectorXd bias = InverseDynamics(model, data, q, v, zero);
  const Eigen::VectorXd tau = InverseDynamics(model, data, q, v, a);
  EXPECT_LT((tau - bias - M * a).cwiseAbs().maxCoeff(), 1e-9 * std::max(1.0, tau.cwiseAbs().maxCoeff()));
  EXPECT_LT((ForwardDynamics(model, data, q, v, tau) - a).cwiseAbs().maxCoeff(), 1e-8);
  // Kinetic energy from body twists equals 1/2 v^T M v.
  EXPECT_NEAR(KineticEnergy(model, data, q, v), 0.5 * v.dot(M * v), 1e-10 * v.dot(M * v));
  // Linear centroidal momentum = total mass times the centre-of-mass velocity.
  const Vector6d h = CentroidalMomentum(model, data, q, v);
  const Eigen::Vector3d com_velocity = CenterOfMassJacobian(model, data, q) * v;
  EXPECT_LT((h.tail<3>() - model.total_mass() * com_velocity).norm(), 1e-10 * std::max(1.0, h.norm()));
}

// A free-floating robot without gravity and without joint torques keeps its kinetic energy and its
// momentum; RK4 on (q, v) with the quaternion integrated in its embedding must keep them to 1e-8 over 1 s.
TEST_P(DynamicsTest, FreeFloatingRk4ConservesEnergyAndMomentum) {
  const Model model = test::LoadRobot(GetParam(), true).WithGravity(Eigen::Vector3d::Zero());
  Data data(model);
  std::mt19937 rng(32);
  const int nv = model.nv();
  Eigen::VectorXd q = RandomConfiguration(model, rng, 1.0);
  Eigen::VectorXd v = 0.5 * RandomVector(nv, rng);
  const Eigen::VectorXd tau = Eigen::VectorXd::Zero(nv);
  const double energy0 = KineticEnergy(model, data, q, v);
  const Vector6d h0 = CentroidalMomentum(model, data, q, v);
  const double dt = 1e-3;
  auto qdot = [&](const Eigen::VectorXd& qs, const Eigen::VectorXd& vs) { return ConfigurationRate(model, qs, vs); };
  auto vdot = [&](const Eigen::VectorXd& qs, const Eigen::VectorXd& vs) {
    return Eigen::VectorXd(ForwardDynamics(model, data, qs, vs, tau));
  };
  for (int step = 0; step < 1000; ++step) {
    const Eigen::VectorXd k1q = qdot(q, v), k1v = vdot(q, v);
    const Eigen::VectorXd q2 = q + 0.5 * dt * k1q, v2 = v + 0.5 * dt * k1v;
    const Eigen::VectorXd k2q = qdot(q2, v2), k2v = vdot(q2, v2);
    const Eigen::VectorXd q3 = q + 0.5 * dt * k2q, v3 = v + 0.5 * dt * k2v;
    const Eigen::VectorXd k3q = qdot(q3, v3), k3v = vdot(q3, v3);
    const Eigen::VectorXd q4 = q + dt * k3q, v4 = v + dt * k3v;
    const Eigen::VectorXd k4q = qdot(q4, v4), k4v = vdot(q4, v4);
    q += dt / 6.0 * (k1q + 2 * k2q + 2 * k3q + k4q);
    v += dt / 6.0 * (k1v + 2 * k2v + 2 * k3v + k4v);
    NormalizeConfiguration(model, q);
  }
  const double energy1 = KineticEnergy(model, data, q, v);
  EXPECT_GT(energy0, 1.0);
  EXPECT_LT(std::abs(energy1 - energy0), 1e-8 * energy0);
  const Vector6d h1 = CentroidalMomentum(model, data, q, v);
  EXPECT_LT((h1 - h0).norm(), 1e-8 * std::max(1.0, h0.norm()));
}

INSTANTIATE_TEST_SUITE_P(Robots, DynamicsTest,
                         ::testing::Values(test::AtlasUrdf(), test::DrcHuboUrdf(), test::HumanoidUrdf()),
                         [](const auto& info) { return test::RobotName(info.param); });

// With gravity, a fixed-base robot without torques keeps kinetic + potential energy (checks the gravity sign of
// ForwardDynamics against PotentialEnergy).
TEST(DynamicsEnergyTest, FixedBaseUnderGravityConservesTotalEnergy) {
  const Model model = test::LoadRobot(test::HumanoidUrdf(), false);
  Data data(model);
  std::mt19937 rng(33);
  Eigen::VectorXd q = RandomConfiguration(model, rng, 0.5);
  Eigen::VectorXd v = 0.5 * RandomVector(model.nv(), rng);
  const Eigen::VectorXd tau = Eigen::VectorXd::Zero(model.nv());
  auto energy = [&] { return KineticEnergy(model, data, q, v) + PotentialEnergy(model, data, q); };
  const double e0 = energy();
  const double dt = 5e-4;
  for (int step = 0; step < 400; ++step) {
    auto f = [&](const Eigen::VectorXd& qs, const Eigen::VectorXd& vs) {
      return Eigen::VectorXd(ForwardDynamics(model, data, qs, vs, tau));
    };
    const Eigen::VectorXd k1v = f(q, v), k1q = v;
    const Eigen::VectorXd k2q = v + 0.5 * dt * k1v, k2v = f(q + 0.5 * dt * k1q, k2q);
    const Eigen::VectorXd k3q = v + 0.5 * dt * k2v, k3v = f(q + 0.5 * dt * k2q, k3q);
    const Eigen::VectorXd k4q = v + dt * k3v, k4v = f(q + dt * k3q, k4q);
    q += dt / 6.0 * (k1q + 2 * k2q + 2 * k3q + k4q);
    v += dt / 6.0 * (k1v + 2 * k2v + 2 * k3v + k4v);
  }
  // The robot falls: potential energy turns into kinetic energy, the sum stays.
  EXPECT_GT(KineticEnergy(model, data, q, v), 1.0);
  EXPECT_LT(std::abs(energy() - e0), 1e-8 * std::max(1.0, std::abs(e0)));
}

// The body accelerations of ForwardKinematics are the time derivatives of the body twists along a trajectory.
TEST(DynamicsEnergyTest, ForwardKinematicsAccelerationsDifferentiateTheTwists) {
  const Model model = test::LoadRobot(test::AtlasUrdf(), false);
  Data data(model);
  std::mt19937 rng(34);
  const Eigen::VectorXd q = RandomConfiguration(model, rng, 1.0);
  const Eigen::VectorXd v = RandomVector(model.nv(), rng), a = RandomVector(model.nv(), rng);
  const double h = 1e-6;
  ForwardKinematics(model, data, q + h * v + 0.5 * h * h * a, v + h * a);
  const std::vector<Vector6d> plus = data.v;
  ForwardKinematics(model, data, q - h * v + 0.5 * h * h * a, v - h * a);
  const std::vector<Vector6d> minus = data.v;
  ForwardKinematics(model, data, q, v, a);
  for (int i = 1; i < model.num_bodies(); ++i) {
    const std::size_t ui = static_cast<std::size_t>(i);
    EXPECT_LT((data.a[ui] - (plus[ui] - minus[ui]) / (2 * h)).cwiseAbs().maxCoeff(), 1e-6) << model.body(i).name;
  }
}

// A cart (prismatic along x) carrying a pendulum (revolute about y): inverse dynamics, mass matrix and gravity
// torques against the textbook equations of motion.
TEST(DynamicsAnalyticTest, CartPoleMatchesItsEquationsOfMotion) {
  const double mc = 2.0, mp = 0.7, l = 0.6, i = 0.01, g = 9.81;
  ModelBuilder builder("cart_pole");
  Body cart;
  cart.name = "cart";
  cart.inertia = SpatialInertia::FromMassComInertia(mc, Eigen::Vector3d::Zero(), 0.1 * Eigen::Matrix3d::Identity());
  Joint slider;
  slider.name = "slider";
  slider.type = JointType::kPrismatic;
  slider.axis = Eigen::Vector3d::UnitX();
  const int cart_index = builder.AddBody(0, cart, slider);
  Body pole;
  pole.name = "pole";
  pole.inertia = SpatialInertia::FromMassComInertia(mp, Eigen::Vector3d(0, 0, -l), i * Eigen::Matrix3d::Identity());
  Joint hinge;
  hinge.name = "hinge";
  hinge.type = JointType::kRevolute;
  hinge.axis = Eigen::Vector3d::UnitY();
  builder.AddBody(cart_index, pole, hinge);
  const Model model = builder.Build();
  Data data(model);
  const Eigen::Vector2d q(0.3, 0.8), v(-0.5, 1.7), a(0.9, -2.1);
  const double s = std::sin(q[1]), c = std::cos(q[1]);
  // Pole centre of mass (x - l sin(theta), 0, -l cos(theta)).
  Eigen::Matrix2d M;
  M << mc + mp, -mp * l * c, -mp * l * c, mp * l * l + i;
  const Eigen::Vector2d bias(mp * l * s * v[1] * v[1], mp * g * l * s);
  EXPECT_LT((MassMatrix(model, data, q) - M).cwiseAbs().maxCoeff(), 1e-12);
  EXPECT_LT((InverseDynamics(model, data, q, v, a) - (M * a + bias)).cwiseAbs().maxCoeff(), 1e-12);
  EXPECT_LT((GravityTorques(model, data, q) - Eigen::Vector2d(0.0, mp * g * l * s)).cwiseAbs().maxCoeff(), 1e-12);
  EXPECT_NEAR(PotentialEnergy(model, data, q), -mp * g * l * c, 1e-12);
  EXPECT_NEAR(KineticEnergy(model, data, q, v), 0.5 * v.dot(M * v), 1e-12);
}

TEST(DynamicsErrorsTest, SizesAndMasslessModelsAreReported) {
  const Model model = test::LoadRobot(test::AtlasUrdf(), false);
  Data data(model);
  const Eigen::VectorXd q = Eigen::VectorXd::Zero(model.nq());
  CAIRN_EXPECT_THROWS_WITH(InverseDynamics(model, data, q, Eigen::VectorXd::Zero(3), Eigen::VectorXd::Zero(model.nv())),
                           std::invalid_argument, "InverseDynamics", "v has size 3", "nv = 27");
  CAIRN_EXPECT_THROWS_WITH(ForwardDynamics(model, data, q, q, Eigen::VectorXd::Zero(2)), std::invalid_argument,
                           "ForwardDynamics", "size 2");
  // A joint carrying nothing makes M singular.
  ModelBuilder builder("massless");
  Body body;
  body.name = "ghost";
  Joint joint;
  joint.name = "hinge";
  joint.type = JointType::kRevolute;
  builder.AddBody(0, body, joint);
  const Model ghost = builder.Build();
  Data ghost_data(ghost);
  const Eigen::VectorXd one = Eigen::VectorXd::Zero(1);
  CAIRN_EXPECT_THROWS_WITH(ForwardDynamics(ghost, ghost_data, one, one, one), std::runtime_error, "massless",
                           "not positive definite");
  CAIRN_EXPECT_THROWS_WITH(CenterOfMass(ghost, ghost_data, one), std::runtime_error, "massless", "zero total mass");
}

}  // namespace
}  // namespace cairn::multibody
