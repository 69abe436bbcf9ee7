// JointPdController: a joint tracking a sine has the steady-state error its gains predict, torques saturate at the
// URDF effort limits, and the control YAML is validated with one-line messages.

#include <cmath>
#include <complex>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include <cairn/multibody/model_builder.h>
#include <cairn/multibody/plant/bullet_plant.h>
#include <cairn/multibody/plant/joint_pd_controller.h>

#include "expect_throws.h"
#include "test_models.h"
#include "test_paths.h"

namespace cairn::multibody {
namespace {

constexpr double kPi = 3.14159265358979323846;

// One link turning about the vertical axis (gravity does no work on it): inertia I = 0.1 kg m^2 about the hinge.
Model Turntable(double effort_limit) {
  ModelBuilder builder("turntable");
  Body arm;
  arm.name = "arm";
  arm.inertia = SpatialInertia::FromMassComInertia(1.0, Eigen::Vector3d(0.3, 0.0, 0.0), 0.01 * Eigen::Matrix3d::Identity());
  Joint hinge;
  hinge.name = "hinge";
  hinge.type = JointType::kRevolute;
  hinge.axis = Eigen::Vector3d::UnitZ();
  hinge.effort_limit = effort_limit;
  builder.AddBody(0, arm, hinge);
  return builder.Build();
}

TEST(JointPdControllerTest, SineTrackingErrorIsWhatTheGainsPredict) {
  const Model model = Turntable(100.0);
  const double I = 0.01 + 0.3 * 0.3, kp = 100.0, kd = 5.0, A = 0.3, w = 2.0 * kPi;
  const JointPdController pd(model, Eigen::VectorXd::Constant(1, kp), Eigen::VectorXd::Constant(1, kd));
  BulletPlantOptions options;
  options.contacts = false;
  BulletPlant plant(model, {}, options);
  plant.SetState(Eigen::VectorXd::Zero(1), Eigen::VectorXd::Constant(1, A * w));
  // Continuous time: I e'' + kd e' + kp e = I q_ref'' for e = q_ref - q, so the steady error amplitude is
  // I A w^2 / |kp - I w^2 + i kd w|. The plant samples the PD law at h and integrates semi-implicitly
  // (v+ = v + h tau / I, q+ = q + h v+); with q_n = Q z^n, z = exp(i w h), that gives exactly
  // Q [(z - 1)(z - 1 + h kd / I) / (h z) + h kp / I] = (h / I) A (kp + i w kd), and the error amplitude |A - Q|.
  const double continuous = I * A * w * w / std::abs(std::complex<double>(kp - I * w * w, kd * w));
  const double h = options.time_step;
  const std::complex<double> z = std::exp(std::complex<double>(0.0, w * h));
  const std::complex<double> Q = (h / I) * A * std::complex<double>(kp, w * kd) /
                                 ((z - 1.0) * (z - 1.0 + h * kd / I) / (h * z) + h * kp / I);
  const double predicted = std::abs(A - Q);
  double worst = 0.0;
  for (int step = 0; step < 10000; ++step) {
    const double t = plant.time();
    const Eigen::VectorXd q_ref = Eigen::VectorXd::Constant(1, A * std::sin(w * t));
    const Eigen::VectorXd v_ref = Eigen::VectorXd::Constant(1, A * w * std::cos(w * t));
    plant.Step(pd.Torques(plant.positions(), plant.velocities(), q_ref, v_ref));
    const double t1 = plant.time();
    // After the transient (time constant 2 I / kd = 0.04 s) has died out.
    if (t1 > 5.0) worst = std::max(worst, std::abs(A * std::sin(w * t1) - plant.positions()[0]));
  }
  // Stated tolerance: 0.1 % of the discrete prediction (the samples miss the peak by at most cos(w h / 2));
  // the continuous-time value differs by the sampling's own effect, a few per cent at these gains.
  EXPECT_NEAR(worst, predicted, 1e-3 * predicted);
  EXPECT_NEAR(worst, continuous, 0.05 * continuous);
  RecordProperty("tracking_error", std::to_string(worst) + " vs " + std::to_string(predicted) + " (continuous " +
                                       std::to_string(continuous) + ")");
}

TEST(JointPdControllerTest, TorquesSaturateAtTheEffortLimit) {
  const Model model = Turntable(2.5);
  const JointPdController pd(model, Eigen::VectorXd::Constant(1, 100.0), Eigen::VectorXd::Constant(1, 1.0));
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(1);
  EXPECT_DOUBLE_EQ(pd.Torques(zero, zero, Eigen::VectorXd::Constant(1, 1.0), zero)[0], 2.5);
  EXPECT_DOUBLE_EQ(pd.Torques(zero, zero, Eigen::VectorXd::Constant(1, -1.0), zero)[0], -2.5);
  EXPECT_DOUBLE_EQ(pd.Torques(zero, zero, Eigen::VectorXd::Constant(1, 0.01), zero)[0], 1.0);
  CAIRN_EXPECT_THROWS_WITH(pd.Torques(zero, zero, Eigen::VectorXd::Constant(1, std::nan("")), zero),
                           std::invalid_argument, "q_ref[0] is nan");
  CAIRN_EXPECT_THROWS_WITH(JointPdController(model, Eigen::VectorXd::Constant(1, -1.0), zero), std::invalid_argument,
                           "joint 'hinge' has kp -1");
}

std::string WriteFile(const std::string& name, const std::string& text) {
  const std::string path = std::string(CAIRN_BINARY_DIR) + "/" + name;
  std::ofstream(path) << text;
  return path;
}

TEST(JointPdControllerTest, LoadsTheHumanoidGainsAndRejectsBadFiles) {
  const Model model = test::LoadRobot(test::HumanoidUrdf(), true);
  const JointPdController pd =
      JointPdController::Load(model, std::string(CAIRN_SOURCE_DIR) + "/data/robots/cairn_humanoid_control.yaml");
  EXPECT_DOUBLE_EQ(pd.kp()[model.joint(model.GetJointIndex("l_knee")).idx_v], 3000.0);
  EXPECT_DOUBLE_EQ(pd.kd()[model.joint(model.GetJointIndex("r_wrist_roll")).idx_v], 0.1);
  EXPECT_DOUBLE_EQ(pd.kp()[0], 0.0);  // the floating base is not actuated
  const Model turntable = Turntable(1.0);
  CAIRN_EXPECT_THROWS_WITH(JointPdController::Load(turntable, WriteFile("pd_missing.yaml", "gains: {}\n")),
                           std::invalid_argument, "joint 'hinge' of 'turntable' is in no group");
  CAIRN_EXPECT_THROWS_WITH(
      JointPdController::Load(turntable,
                              WriteFile("pd_unknown.yaml", "gains:\n  a: {joints: [hinge, elbow], kp: 1, kd: 1}\n")),
      std::invalid_argument, "names 'elbow', which is not a joint");
  CAIRN_EXPECT_THROWS_WITH(
      JointPdController::Load(turntable, WriteFile("pd_nan.yaml", "gains:\n  a: {joints: [hinge], kp: .nan, kd: 1}\n")),
      std::invalid_argument, "kp");
  CAIRN_EXPECT_THROWS_WITH(
      JointPdController::Load(turntable, WriteFile("pd_twice.yaml", "gains:\n  a: {joints: [hinge], kp: 1, kd: 1}\n"
                                                                     "  b: {joints: [hinge], kp: 1, kd: 1}\n")),
      std::invalid_argument, "joint 'hinge' is in both gains.a and gains.b");
}

}  // namespace
}  // namespace cairn::multibody
