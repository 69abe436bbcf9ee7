// Gradient checks and values of the whole-body evaluators of problem (2.9).
#include <cmath>
#include <limits>
#include <random>

#include <gtest/gtest.h>

#include <cairn/multibody/center_of_mass.h>
#include <cairn/multibody/configuration.h>
#include <cairn/multibody/data.h>
#include <cairn/multibody/kinematics.h>
#include <cairn/optimization/check_gradients.h>
#include <cairn/planning/trajectory/base_rotation_change.h>
#include <cairn/planning/trajectory/center_of_mass_projection.h>
#include <cairn/planning/trajectory/collision_penalty.h>
#include <cairn/planning/trajectory/configuration_chart.h>
#include <cairn/planning/trajectory/environment_from_terrain.h>
#include <cairn/planning/trajectory/frame_pose_error.h>
#include <cairn/planning/trajectory/quaternion_norm_error.h>
#include <cairn/planning/trajectory/static_torque_residual.h>
#include <cairn/planning/trajectory/waist_roll_error.h>

#include "expect_throws.h"
#include "test_robot.h"

namespace cairn::planning {
namespace {

using optimization::CheckGradients;
using test::Humanoid;

// A random configuration with a deliberately non-unit quaternion (the evaluators read it normalised).
Eigen::VectorXd RandomPoint(unsigned seed, double quaternion_scale = 1.3) {
  std::mt19937 rng(seed);
  Eigen::VectorXd q = multibody::RandomConfiguration(*Humanoid(), rng, 0.5);
  q.segment<4>(3) *= quaternion_scale;
  return q;
}

Eigen::VectorXd JointScale() {
  const ConfigurationChart chart(*Humanoid());
  Eigen::VectorXd scale(static_cast<Eigen::Index>(chart.joint_velocities().size()));
  for (std::size_t i = 0; i < chart.joint_velocities().size(); ++i) {
    scale(static_cast<Eigen::Index>(i)) = 1.0 / Humanoid()->effort_limits()(chart.joint_velocities()[i]);
  }
  return scale;
}

TEST(ConfigurationChartTest, NormalisesTheQuaternionAndRejectsAZeroOne) {
  const ConfigurationChart chart(*Humanoid());
  EXPECT_TRUE(chart.has_floating_base());
  Eigen::VectorXd q = RandomPoint(1, 2.0);
  EXPECT_NEAR(chart.Normalized(q).segment<4>(3).norm(), 1.0, 1e-14);
  q.segment<4>(3).setZero();
  CAIRN_EXPECT_THROWS_WITH(chart.Normalized(q), std::invalid_argument, "quaternion has norm 0");
}

TEST(FramePoseErrorTest, IsZeroAtTheFramePoseAndItsJacobianMatchesFiniteDifferences) {
  const auto model = Humanoid();
  for (unsigned seed = 1; seed <= 3; ++seed) {
    const Eigen::VectorXd q = RandomPoint(seed);
    multibody::Data data(*model);
    multibody::ForwardKinematics(*model, data, ConfigurationChart(*model).Normalized(q));
    const multibody::Pose X = multibody::FramePose(*model, data, model->GetFrameIndex("l_sole"));
    const FramePoseError at(model, "l_sole", X);
    EXPECT_LT(at.Eval(q).norm(), 1e-12);
    // A target rotated by about 0.4 rad and moved, so the rotation rows are far from the identity.
    const Eigen::Matrix3d R = Eigen::AngleAxisd(0.4, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
    const FramePoseError error(model, "l_sole", multibody::Pose(X.rotation() * R, X.translation() + Eigen::Vector3d(0.1, 0, 0)));
    EXPECT_NEAR(error.Eval(q).tail<3>().norm(), 0.4, 1e-9);
    const auto check = CheckGradients(error, q, 1e-6);
    EXPECT_TRUE(check.passed) << check.ToString();
  }
  CAIRN_EXPECT_THROWS_WITH(FramePoseError(model, "l_sol", multibody::Pose()), std::invalid_argument, "l_sol");
}

TEST(CenterOfMassProjectionTest, GivesAComAndItsJacobian) {
  const auto model = Humanoid();
  const Eigen::VectorXd q = RandomPoint(4);
  multibody::Data data(*model);
  const Eigen::Vector3d com = multibody::CenterOfMass(*model, data, ConfigurationChart(*model).Normalized(q));
  Eigen::MatrixXd A(3, 2);
  A << 1, 0, 0, 1, 0.6, -0.8;
  const CenterOfMassProjection projection(model, A, Eigen::Vector3d(0.1, 0.2, 0.3));
  EXPECT_LT((projection.Eval(q) - (A * com.head<2>() - Eigen::Vector3d(0.1, 0.2, 0.3))).norm(), 1e-12);
  const auto check = CheckGradients(projection, q, 1e-6);
  EXPECT_TRUE(check.passed) << check.ToString();
  CAIRN_EXPECT_THROWS_WITH(CenterOfMassProjection(model, Eigen::MatrixXd(2, 3)), std::invalid_argument, "2 columns");
}

TEST(WaistRollErrorTest, IsZeroForPitchAndYawAndItsJacobianMatchesFiniteDifferences) {
  const auto model = Humanoid();
  const WaistRollError roll(model, "pelvis");
  Eigen::VectorXd q = test::BentKneePosture(*model);
  const Eigen::Quaterniond pitch_yaw(Eigen::AngleAxisd(0.5, Eigen::Vector3d::UnitZ()) *
                                     Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitY()));
  q.segment<4>(3) << pitch_yaw.w(), pitch_yaw.x(), pitch_yaw.y(), pitch_yaw.z();
  EXPECT_NEAR(roll.Eval(q)(0), 0.0, 1e-12);
  // The waist joint's own roll moves the torso, not the pelvis (the thesis' waist link).
  q(model->joint(model->GetJointIndex("waist_roll")).idx_q) = 0.2;
  EXPECT_NEAR(roll.Eval(q)(0), 0.0, 1e-12);
  const Eigen::Quaterniond rolled(Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitY()) *
                                  Eigen::AngleAxisd(0.2, Eigen::Vector3d::UnitX()));
  q.segment<4>(3) << rolled.w(), rolled.x(), rolled.y(), rolled.z();
  EXPECT_NEAR(roll.Eval(q)(0), std::sin(0.2) * std::cos(0.3), 1e-9);
  for (unsigned seed = 5; seed <= 6; ++seed) {
    const auto check = CheckGradients(roll, RandomPoint(seed), 1e-6);
    EXPECT_TRUE(check.passed) << check.ToString();
  }
}

TEST(QuaternionNormErrorTest, GradientAndHessianMatchFiniteDifferences) {
  const QuaternionNormError norm;
  const Eigen::Vector4d x(0.9, 0.1, -0.3, 0.2);
  EXPECT_NEAR(norm.Eval(x)(0), x.squaredNorm() - 1.0, 1e-15);
  const auto check = CheckGradients(norm, x, 1e-6);
  EXPECT_TRUE(check.passed) << check.ToString();
}

TEST(BaseRotationChangeTest, MeasuresTheRotationAngleBetweenTwoWaypointsAndHasExactDerivatives) {
  const BaseRotationChange change;
  const Eigen::Quaterniond a(Eigen::AngleAxisd(0.4, Eigen::Vector3d(0.2, 0.3, 1.0).normalized()));
  for (const double theta : {0.0, 0.05, 0.4}) {
    const Eigen::Quaterniond b = a * Eigen::Quaterniond(Eigen::AngleAxisd(theta, Eigen::Vector3d(1.0, -0.5, 0.3).normalized()));
    Eigen::VectorXd x(8);
    x << a.w(), a.x(), a.y(), a.z(), b.w(), b.x(), b.y(), b.z();
    // |r| = 4 sin(theta / 4): the rotation angle to second order.
    EXPECT_NEAR(change.Eval(x).norm(), 4.0 * std::sin(0.25 * theta), 1e-12);
    EXPECT_NEAR(change.Eval(x).norm(), theta, theta * theta * theta / 90.0 + 1e-15);  // 4 sin(t/4) = t - t^3/96 + ...
    const auto check = CheckGradients(change, x, 1e-8);
    EXPECT_TRUE(check.passed) << check.ToString();
  }
  EXPECT_TRUE(change.has_hessian());
  EXPECT_TRUE(change.hessian_pattern().empty());  // linear: the least-squares J'J is the exact Hessian
}

TEST(StaticTorqueResidualTest, SingleSupportTorquesAreThoseOfTheChainFromTheFoot) {
  const auto model = Humanoid();
  const ConfigurationChart chart(*model);
  const Eigen::VectorXd ones = Eigen::VectorXd::Ones(static_cast<Eigen::Index>(chart.joint_coordinates().size()));
  const StaticTorqueResidual left(model, {{"l_sole", 1.0}}, ones);
  const Eigen::VectorXd q = test::BentKneePosture(*model);
  const Eigen::VectorXd tau = left.JointTorques(q);
  // Standing on the left foot, the left knee holds nearly the whole weight; the right (swing) knee only its shank
  // and foot: the pelvis-rooted gravity torques would make both small.
  const auto knee = [&](const char* name) {
    const int v = model->joint(model->GetJointIndex(name)).idx_v;
    for (std::size_t i = 0; i < chart.joint_velocities().size(); ++i) {
      if (chart.joint_velocities()[i] == v) return tau(static_cast<Eigen::Index>(i));
    }
    return 0.0;
  };
  EXPECT_GT(std::abs(knee("l_knee")), 10.0 * std::abs(knee("r_knee")));
  // Pure vertical translation of the whole robot leaves the torques unchanged.
  Eigen::VectorXd lifted = q;
  lifted(2) += 0.3;
  EXPECT_LT((left.JointTorques(lifted) - tau).norm(), 1e-9);
  for (unsigned seed = 7; seed <= 9; ++seed) {
    const StaticTorqueResidual shared(model, {{"l_sole", 0.3}, {"r_sole", 0.7}}, JointScale());
    const auto check = CheckGradients(shared, RandomPoint(seed), 1e-6);
    EXPECT_TRUE(check.passed) << check.ToString();
  }
  CAIRN_EXPECT_THROWS_WITH(StaticTorqueResidual(model, {{"l_sole", 0.5}}, ones), std::invalid_argument,
                           "sum to 0.5");
}

TEST(CollisionPenaltyTest, PenalisesABarAtTheHeadWithAnExactGradient) {
  const auto model = Humanoid();
  Eigen::VectorXd q = test::BentKneePosture(*model);
  multibody::Data data(*model);
  multibody::ForwardKinematics(*model, data, q);
  const Eigen::Vector3d head = data.X_world[static_cast<std::size_t>(model->GetBodyIndex("head"))].translation();
  // A bar whose underside is 1 cm above the head sphere (centre 0.06 m above the head frame, radius 0.1 m).
  EnvironmentBox bar{"bar", Eigen::Vector3d(0.1, 2.0, 0.1),
                     multibody::Pose(Eigen::Matrix3d::Identity(), head + Eigen::Vector3d(0.0, 0, 0.06 + 0.1 + 0.01 + 0.05))};
  const CollisionPenalty penalty("collision", model, {bar}, {"l_foot", "r_foot"}, 0.025, 0.01);
  std::string which;
  const double d = penalty.MinimumEnvironmentDistance(q, &which);
  EXPECT_NEAR(d, 0.01, 1e-9) << which;
  EXPECT_EQ(which, "head_sphere - bar");
  // Only the bar pair is within its margin: the robot's own pairs closer than 1 cm at the neutral posture are
  // excluded, the others are further apart.
  ASSERT_EQ(penalty.PairsWithinMargin(q).size(), 1u);
  EXPECT_NEAR(penalty.Eval(q)(0), 0.015 * 0.015, 1e-12);
  Eigen::VectorXd perturbed = q;
  perturbed.segment<4>(3) *= 1.2;
  perturbed(model->joint(model->GetJointIndex("neck_pitch")).idx_q) = 0.1;
  const auto check = CheckGradients(penalty, perturbed, 1e-6);
  EXPECT_TRUE(check.passed) << check.ToString();
  // Between two waypoints: the sample's gradient splits between them.
  Eigen::VectorXd lowered = q;
  lowered(2) -= 0.05;
  Eigen::VectorXd both(2 * model->nq());
  both << perturbed, lowered;
  const CollisionPenalty sample("collision_sample", model, {bar}, {}, 0.025, 0.01, 0.5);
  const auto sample_check = CheckGradients(sample, both, 1e-6);
  EXPECT_TRUE(sample_check.passed) << sample_check.ToString();
  // The ground plane, in closed form: a robot standing 1 cm too low has its soles' corners in the margin.
  Eigen::VectorXd low = q;
  low(2) -= 0.01 + 0.0;
  const CollisionPenalty ground("ground", model, {}, {}, 0.025, 0.0, 0.0, /*ground_height=*/0.0);
  multibody::ForwardKinematics(*model, data, low);
  const double sole_z = data.X_world[static_cast<std::size_t>(model->GetBodyIndex("l_sole"))].translation().z();
  std::string ground_pair;
  EXPECT_NEAR(ground.MinimumEnvironmentDistance(low, &ground_pair), sole_z, 1e-9);
  EXPECT_NE(ground_pair.find("sole_box - ground"), std::string::npos) << ground_pair;
  for (unsigned seed = 11; seed <= 13; ++seed) {
    Eigen::VectorXd random = RandomPoint(seed);
    random(2) = 0.5;
    const auto ground_check = CheckGradients(ground, random, 1e-5);
    EXPECT_TRUE(ground_check.passed) << ground_check.ToString();
  }
  // Far away: zero penalty.
  Eigen::VectorXd away = q;
  away(0) += 3.0;
  EXPECT_EQ(penalty.Eval(away)(0), 0.0);
}

// Over a terrain the ground term follows its cells: on a uniform 20-degree slope the clearance is each support
// point's distance from the slope's plane (checked against the box corners directly), its gradient is exact, a
// level terrain at 0.3 m agrees with the plane at 0.3 m, and off the map the ground_height plane applies.
TEST(CollisionPenaltyTest, TheGroundFollowsATerrain) {
  const auto model = Humanoid();
  const double a = 20.0 * M_PI / 180.0;
  const Eigen::Vector3d n(-std::sin(a), 0.0, std::cos(a));
  auto slope = std::make_shared<TerrainMap>(Eigen::Vector2d(-2.0, -2.0), 80, 80, 0.05);
  auto level = std::make_shared<TerrainMap>(Eigen::Vector2d(-2.0, -2.0), 80, 80, 0.05);
  for (int row = 0; row < 80; ++row) {
    for (int col = 0; col < 80; ++col) {
      slope->SetCell(col, row, slope->CellCenter(col, row).x() * std::tan(a), n, 1.0);
      level->SetCell(col, row, 0.3, Eigen::Vector3d::UnitZ(), 1.0);
    }
  }
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const CollisionPenalty on_slope("ground", model, {}, {}, 0.025, 0.0, 0.0, nan, CollisionHessian::kDifferences,
                                  slope);
  Eigen::VectorXd q = test::BentKneePosture(*model);
  q(2) = 0.85;
  multibody::Data data(*model);
  multibody::ForwardKinematics(*model, data, q);
  double expected = std::numeric_limits<double>::infinity();
  for (int b = 1; b < model->num_bodies(); ++b) {
    for (const multibody::Geometry& g : model->body(b).collisions) {
      if (g.type != multibody::GeometryType::kBox) continue;
      for (int corner = 0; corner < 8; ++corner) {
        const Eigen::Vector3d sign((corner & 1) ? 0.5 : -0.5, (corner & 2) ? 0.5 : -0.5, (corner & 4) ? 0.5 : -0.5);
        const Eigen::Vector3d p = data.X_world[static_cast<std::size_t>(b)] * (g.X_BG * sign.cwiseProduct(g.size));
        expected = std::min(expected, n.dot(p));
      }
    }
  }
  std::string which;
  const double d = on_slope.MinimumEnvironmentDistance(q, &which);
  EXPECT_LT(d, 0.1);  // the toes reach towards the slope rising ahead
  // The map keeps heights and normals in single precision.
  EXPECT_NEAR(d, expected, 1e-7) << which;  // (the lowest support point here is a box corner)
  EXPECT_NE(which.find(" - ground"), std::string::npos) << which;
  for (unsigned seed = 21; seed <= 23; ++seed) {
    Eigen::VectorXd random = RandomPoint(seed);
    random(2) = 0.6;
    const auto check = CheckGradients(on_slope, random, 1e-5);
    EXPECT_TRUE(check.passed) << check.ToString();
  }
  const CollisionPenalty on_level("ground", model, {}, {}, 0.025, 0.0, 0.0, nan, CollisionHessian::kDifferences,
                                  level);
  const CollisionPenalty plane("ground", model, {}, {}, 0.025, 0.0, 0.0, 0.3);
  Eigen::VectorXd low = q;
  low(2) = 0.3 + 0.83;
  EXPECT_GT(plane.Eval(low)(0), 0.0);
  EXPECT_NEAR(on_level.Eval(low)(0), plane.Eval(low)(0), 1e-7);
  Eigen::VectorXd off_map = low;
  off_map(0) = 5.0;
  EXPECT_EQ(on_level.Eval(off_map)(0), 0.0);  // no ground there: ground_height is NaN
  const CollisionPenalty fallback("ground", model, {}, {}, 0.025, 0.0, 0.0, 0.3, CollisionHessian::kDifferences,
                                  level);
  EXPECT_EQ(fallback.Eval(off_map)(0), plane.Eval(off_map)(0));
}

// Perceived space: a box that is there with probability p weighs its hinge by p, and the terrain's voxels become
// such boxes.
TEST(CollisionPenaltyTest, WeighsUncertainBoxesByTheirProbability) {
  const auto model = Humanoid();
  const Eigen::VectorXd q = test::BentKneePosture(*model);
  multibody::Data data(*model);
  multibody::ForwardKinematics(*model, data, q);
  const Eigen::Vector3d head = data.X_world[static_cast<std::size_t>(model->GetBodyIndex("head"))].translation();
  EnvironmentBox bar{"bar", Eigen::Vector3d(0.1, 2.0, 0.1),
                     multibody::Pose(Eigen::Matrix3d::Identity(), head + Eigen::Vector3d(0.0, 0, 0.06 + 0.1 + 0.01 + 0.05))};
  const CollisionPenalty certain("collision", model, {bar}, {"l_foot", "r_foot"}, 0.025, 0.01);
  bar.probability = 0.4;
  const CollisionPenalty uncertain("collision", model, {bar}, {"l_foot", "r_foot"}, 0.025, 0.01);
  EXPECT_NEAR(uncertain.Eval(q)(0), 0.4 * certain.Eval(q)(0), 1e-15);
  Eigen::VectorXd perturbed = q;
  perturbed(model->joint(model->GetJointIndex("neck_pitch")).idx_q) = 0.1;
  const auto check = CheckGradients(uncertain, perturbed, 1e-6);
  EXPECT_TRUE(check.passed) << check.ToString();
  bar.probability = 0.0;
  CAIRN_EXPECT_THROWS_WITH(CollisionPenalty("collision", model, {bar}, {}, 0.025, 0.01), std::invalid_argument,
                           "environment box 'bar' has probability 0; give a probability in (0, 1]");

  TerrainMap terrain(Eigen::Vector2d(0.0, 0.0), 10, 10, 0.05);
  terrain.AddObstacle({"crate", Eigen::Vector3d(0.2, 0.2, 0.1), Eigen::Vector3d(0.05, 0.05, 0.1), 0.0});
  terrain.SetOccupiedVoxels({{Eigen::Vector3d(0.3, 0.3, 0.6), 0.7}, {Eigen::Vector3d(0.35, 0.3, 0.6), 0.55}}, 0.05);
  const std::vector<EnvironmentBox> environment = EnvironmentFromTerrain(terrain);
  ASSERT_EQ(environment.size(), 3u);
  EXPECT_EQ(environment[0].name, "crate");
  EXPECT_EQ(environment[0].probability, 1.0);
  EXPECT_EQ(environment[2].name, "voxel 1");
  EXPECT_EQ(environment[2].size, Eigen::Vector3d::Constant(0.05));
  EXPECT_EQ(environment[2].X_WB.translation(), Eigen::Vector3d(0.35, 0.3, 0.6));
  EXPECT_DOUBLE_EQ(environment[2].probability, 0.55);
}

// With one pair in its margin the penalty is f = h^2 with gradient -2 h J, so its Gauss-Newton Hessian 2 J'J is
// exactly grad f grad f' / (2 f); between waypoints the same matrix splits into blocks by the blend weights.
TEST(CollisionPenaltyTest, GaussNewtonHessianIsTheOuterProductOfThePairGradients) {
  const auto model = Humanoid();
  const Eigen::VectorXd q = test::BentKneePosture(*model);
  multibody::Data data(*model);
  multibody::ForwardKinematics(*model, data, q);
  const Eigen::Vector3d head = data.X_world[static_cast<std::size_t>(model->GetBodyIndex("head"))].translation();
  EnvironmentBox bar{"bar", Eigen::Vector3d(0.1, 2.0, 0.1),
                     multibody::Pose(Eigen::Matrix3d::Identity(), head + Eigen::Vector3d(0.02, 0, 0.06 + 0.1 + 0.01 + 0.05))};
  const CollisionPenalty penalty("collision", model, {bar}, {"l_foot", "r_foot"}, 0.025, 0.01, 0.0,
                                 std::numeric_limits<double>::quiet_NaN(), CollisionHessian::kGaussNewton);
  Eigen::VectorXd scaled = q;
  scaled.segment<4>(3) *= 1.2;  // the same pose, read through the quaternion chart
  ASSERT_EQ(penalty.PairsWithinMargin(scaled).size(), 1u);
  const int nq = model->nq();
  Eigen::VectorXd f(1);
  Eigen::VectorXd gradient(nq);
  penalty.EvalWithJacobian(scaled, f, gradient);
  ASSERT_GT(f(0), 0.0);
  const Eigen::MatrixXd expected = gradient * gradient.transpose() / (2.0 * f(0));
  const auto dense = [](const optimization::Evaluator& e, const Eigen::VectorXd& x, double weight) {
    Eigen::VectorXd values(static_cast<Eigen::Index>(e.hessian_pattern().size()));
    e.EvalHessian(x, Eigen::VectorXd::Constant(1, weight), values);
    Eigen::MatrixXd H = Eigen::MatrixXd::Zero(e.num_inputs(), e.num_inputs());
    for (std::size_t k = 0; k < e.hessian_pattern().size(); ++k) {
      const auto& entry = e.hessian_pattern()[k];
      H(entry.row, entry.col) = H(entry.col, entry.row) = values(static_cast<Eigen::Index>(k));
    }
    return H;
  };
  const Eigen::MatrixXd H = dense(penalty, scaled, 3.0);
  EXPECT_LT((H - 3.0 * expected).cwiseAbs().maxCoeff(), 1e-9 * (1.0 + expected.cwiseAbs().maxCoeff()));

  const CollisionPenalty sample("sample", model, {bar}, {}, 0.025, 0.01, 0.25,
                                std::numeric_limits<double>::quiet_NaN(), CollisionHessian::kGaussNewton);
  Eigen::VectorXd both(2 * nq);
  both << scaled, scaled;
  const Eigen::MatrixXd Hs = dense(sample, both, 1.0);
  EXPECT_LT((Hs.topLeftCorner(nq, nq) - 0.75 * 0.75 * expected).cwiseAbs().maxCoeff(), 1e-9 * (1.0 + expected.norm()));
  EXPECT_LT((Hs.bottomLeftCorner(nq, nq) - 0.25 * 0.75 * expected).cwiseAbs().maxCoeff(), 1e-9 * (1.0 + expected.norm()));
  EXPECT_LT((Hs.bottomRightCorner(nq, nq) - 0.25 * 0.25 * expected).cwiseAbs().maxCoeff(), 1e-9 * (1.0 + expected.norm()));
}

}  // namespace
}  // namespace cairn::planning
