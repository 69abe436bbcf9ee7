// BulletPlant without contacts against Cairn's ForwardDynamics (CRBA + Cholesky, itself cross-checked against
// DART): the same q, v and generalized forces must give the same accelerations, on the project's humanoid and on
// Atlas, so that the plant is the model the planners use.

#include <cmath>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include <cairn/multibody/configuration.h>
#include <cairn/multibody/data.h>
#include <cairn/multibody/dynamics.h>
#include <cairn/multibody/plant/bullet_plant.h>

#include "expect_throws.h"
#include "test_models.h"

namespace cairn::multibody {
namespace {

// Bullet integrates semi-implicitly: v1 = v0 + h a(q0, v0) exactly, so (v1 - v0) / h is Bullet's acceleration up
// to the base's change of frame during the step, O(h |ω| |a|) = 1e-7 at h = 1e-8, and rounding, eps |v| / h = 1e-8.
constexpr double kProbeStep = 1e-8;
// Stated tolerance: max |a_bullet - a_cairn| <= kTolerance * max(1, max |a_cairn|).
constexpr double kTolerance = 1e-7;  // measured: <= 8e-10 (Atlas floating), 1.3e-10 (humanoid)

Eigen::VectorXd BulletAccelerations(BulletPlant& plant, const Eigen::VectorXd& q, const Eigen::VectorXd& v,
                                    const Eigen::VectorXd& tau) {
  plant.SetState(q, v);
  plant.Step(tau);
  return (plant.velocities() - v) / kProbeStep;
}

class BulletCrossCheckTest : public ::testing::TestWithParam<std::tuple<std::string, bool>> {};

TEST_P(BulletCrossCheckTest, AccelerationsWithoutContactsMatchForwardDynamics) {
  const auto& [path, floating] = GetParam();
  const Model model = test::LoadRobot(path, floating);
  BulletPlantOptions options;
  options.time_step = kProbeStep;
  options.contacts = false;  // Atlas' collision shapes are meshes
  BulletPlant plant(model, {}, options);
  Data data(model);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  const int nv = model.nv();
  double worst = 0.0;
  for (int trial = 0; trial < 10; ++trial) {
    const Eigen::VectorXd q = RandomConfiguration(model, rng, 1.0);
    Eigen::VectorXd v(nv), tau(nv);
    for (int i = 0; i < nv; ++i) v[i] = uniform(rng);
    for (int i = 0; i < nv; ++i) tau[i] = 10.0 * uniform(rng);
    const Eigen::VectorXd expected = ForwardDynamics(model, data, q, v, tau);
    const Eigen::VectorXd actual = BulletAccelerations(plant, q, v, tau);
    const double scale = std::max(1.0, expected.cwiseAbs().maxCoeff());
    const double error = (actual - expected).cwiseAbs().maxCoeff() / scale;
    worst = std::max(worst, error);
    EXPECT_LE(error, kTolerance) << "trial " << trial << "\nexpected " << expected.transpose() << "\nactual   "
                                 << actual.transpose();
  }
  std::ostringstream text;
  text << std::scientific << worst;
  RecordProperty("worst_relative_error", text.str());
}

INSTANTIATE_TEST_SUITE_P(Robots, BulletCrossCheckTest,
                         ::testing::Values(std::make_tuple(test::HumanoidUrdf(), true),
                                           std::make_tuple(test::HumanoidUrdf(), false),
                                           std::make_tuple(test::AtlasUrdf(), true),
                                           std::make_tuple(test::AtlasUrdf(), false)),
                         [](const auto& info) {
                           return test::RobotName(std::get<0>(info.param)) +
                                  (std::get<1>(info.param) ? "Floating" : "Fixed");
                         });

TEST(BulletPlantTest, StateRoundTripsInCairnCoordinates) {
  const Model model = test::LoadRobot(test::HumanoidUrdf(), true);
  BulletPlant plant(model, {});
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  const Eigen::VectorXd q = RandomConfiguration(model, rng, 1.0);
  Eigen::VectorXd v(model.nv());
  for (int i = 0; i < model.nv(); ++i) v[i] = uniform(rng);
  plant.SetState(q, v);
  Eigen::VectorXd q_back = plant.positions();
  // q and -q are the same rotation.
  if (q_back.segment<4>(3).dot(q.segment<4>(3)) < 0.0) q_back.segment<4>(3) *= -1.0;
  EXPECT_LE((q_back - q).cwiseAbs().maxCoeff(), 1e-12);
  EXPECT_LE((plant.velocities() - v).cwiseAbs().maxCoeff(), 1e-12);
  EXPECT_EQ(plant.num_links(), 30);
}

TEST(BulletPlantTest, RejectsBadInputWithOneLineReasons) {
  const Model model = test::LoadRobot(test::HumanoidUrdf(), true);
  BulletPlantOptions options;
  options.time_step = 0.02;
  CAIRN_EXPECT_THROWS_WITH(BulletPlant(model, {}, options), std::invalid_argument, "time_step 0.02 s is outside");
  options = BulletPlantOptions();
  options.solver_iterations = 0;
  CAIRN_EXPECT_THROWS_WITH(BulletPlant(model, {}, options), std::invalid_argument, "solver_iterations 0");
  TerrainBox box;
  box.name = "ice";
  box.friction = -0.1;
  CAIRN_EXPECT_THROWS_WITH(BulletPlant(model, {box}), std::invalid_argument, "'ice' has friction -0.1");
  box.friction = 0.5;
  box.size = Eigen::Vector3d(1.0, 0.0, 1.0);
  CAIRN_EXPECT_THROWS_WITH(BulletPlant(model, {box}), std::invalid_argument, "'ice' has size[1] = 0");
  CAIRN_EXPECT_THROWS_WITH(BulletPlant(test::LoadRobot(test::AtlasUrdf(), true), {}), std::invalid_argument,
                           "is a mesh");
  BulletPlant plant(model, {});
  CAIRN_EXPECT_THROWS_WITH(plant.Step(Eigen::VectorXd::Zero(3)), std::invalid_argument, "tau has size 3");
  Eigen::VectorXd q = NeutralConfiguration(model);
  q[10] = std::nan("");
  CAIRN_EXPECT_THROWS_WITH(plant.SetState(q, Eigen::VectorXd::Zero(model.nv())), std::invalid_argument,
                           "q[10] is nan");
}

}  // namespace
}  // namespace cairn::multibody
