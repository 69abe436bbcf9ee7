#include <cairn/multibody/configuration.h>

#include <limits>
#include <random>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "expect_throws.h"
#include "test_models.h"

namespace cairn::multibody {
namespace {

class ConfigurationTest : public ::testing::Test {
 protected:
  const Model model_ = test::LoadRobot(test::AtlasUrdf(), true);
};

TEST_F(ConfigurationTest, NeutralIsIdentityPose) {
  const Eigen::VectorXd q = NeutralConfiguration(model_);
  ASSERT_EQ(q.size(), model_.nq());
  const Joint& root = model_.joint(model_.GetJointIndex("root_joint"));
  EXPECT_EQ(q[root.idx_q + 3], 1.0);
  EXPECT_EQ(q.sum(), 1.0);
}

TEST_F(ConfigurationTest, DifferenceInvertsIntegrate) {
  std::mt19937 rng(7);
  std::normal_distribution<double> normal(0.0, 1.0);
  for (int trial = 0; trial < 20; ++trial) {
    const Eigen::VectorXd q = RandomConfiguration(model_, rng);
    Eigen::VectorXd v(model_.nv());
    for (int i = 0; i < v.size(); ++i) v[i] = normal(rng);
    const Eigen::VectorXd q1 = Integrate(model_, q, v, 0.5);
    EXPECT_TRUE(Difference(model_, q, q1).isApprox(0.5 * v, 1e-10)) << trial;
    EXPECT_LT(Difference(model_, q, q).norm(), 1e-14);
    // Integrating the difference lands on q1 (quaternion up to sign).
    const Eigen::VectorXd back = Integrate(model_, q, Difference(model_, q, q1));
    EXPECT_LT(Difference(model_, q1, back).norm(), 1e-10);
  }
}

TEST_F(ConfigurationTest, ConfigurationRateIsTheDerivativeOfIntegrate) {
  std::mt19937 rng(8);
  std::normal_distribution<double> normal(0.0, 1.0);
  const Eigen::VectorXd q = RandomConfiguration(model_, rng);
  Eigen::VectorXd v(model_.nv());
  for (int i = 0; i < v.size(); ++i) v[i] = normal(rng);
  const double h = 1e-6;
  const Eigen::VectorXd numeric = (Integrate(model_, q, v, h) - Integrate(model_, q, v, -h)) / (2 * h);
  EXPECT_LT((numeric - ConfigurationRate(model_, q, v)).cwiseAbs().maxCoeff(), 1e-8);
}

TEST_F(ConfigurationTest, RandomConfigurationsAreDeterministicAndWithinLimits) {
  std::mt19937 a(3), b(3);
  const Eigen::VectorXd qa = RandomConfiguration(model_, a);
  EXPECT_EQ(qa, RandomConfiguration(model_, b));
  EXPECT_TRUE(IsWithinPositionLimits(model_, qa));
  const Joint& root = model_.joint(model_.GetJointIndex("root_joint"));
  EXPECT_NEAR(qa.segment<4>(root.idx_q + 3).norm(), 1.0, 1e-12);
}

TEST_F(ConfigurationTest, LimitHelpers) {
  Eigen::VectorXd q = NeutralConfiguration(model_);
  const Joint& knee = model_.joint(model_.GetJointIndex("l_leg_kny"));
  q[knee.idx_q] = knee.upper_limit + 0.25;
  EXPECT_FALSE(IsWithinPositionLimits(model_, q));
  EXPECT_TRUE(IsWithinPositionLimits(model_, q, 0.3));
  EXPECT_NEAR(PositionLimitViolation(model_, q)[knee.idx_q], 0.25, 1e-12);
  EXPECT_NEAR(ClampToPositionLimits(model_, q)[knee.idx_q], knee.upper_limit, 1e-12);
  q[knee.idx_q] = knee.lower_limit - 0.5;
  EXPECT_NEAR(PositionLimitViolation(model_, q)[knee.idx_q], -0.5, 1e-12);
  // A NaN tolerance would compare false everywhere and call every configuration out of limits.
  CAIRN_EXPECT_THROWS_WITH(IsWithinPositionLimits(model_, q, std::numeric_limits<double>::quiet_NaN()),
                           std::invalid_argument, "tolerance nan", ">= 0");
  CAIRN_EXPECT_THROWS_WITH(IsWithinPositionLimits(model_, q, -0.1), std::invalid_argument, "tolerance -0.1");
}

TEST_F(ConfigurationTest, RandomConfigurationRefusesANonFiniteRange) {
  std::mt19937 rng(7);
  CAIRN_EXPECT_THROWS_WITH(RandomConfiguration(model_, rng, std::numeric_limits<double>::infinity()),
                           std::invalid_argument, "unlimited_range inf", "finite and >= 0");
  CAIRN_EXPECT_THROWS_WITH(RandomConfiguration(model_, rng, -1.0), std::invalid_argument, "unlimited_range -1");
}

TEST_F(ConfigurationTest, NormalizeAndErrors) {
  Eigen::VectorXd q = NeutralConfiguration(model_);
  const Joint& root = model_.joint(model_.GetJointIndex("root_joint"));
  q.segment<4>(root.idx_q + 3) << 2.0, 0.0, 0.0, 0.0;
  NormalizeConfiguration(model_, q);
  EXPECT_DOUBLE_EQ(q[root.idx_q + 3], 1.0);
  q.segment<4>(root.idx_q + 3).setZero();
  CAIRN_EXPECT_THROWS_WITH(NormalizeConfiguration(model_, q), std::invalid_argument, "root_joint", "(1, 0, 0, 0)");
  CAIRN_EXPECT_THROWS_WITH(Integrate(model_, Eigen::VectorXd::Zero(3), Eigen::VectorXd::Zero(model_.nv())),
                           std::invalid_argument, "q has size 3", "nq = 34");
  CAIRN_EXPECT_THROWS_WITH(Integrate(model_, NeutralConfiguration(model_), Eigen::VectorXd::Zero(2)),
                           std::invalid_argument, "v has size 2", "nv = 33");
}

}  // namespace
}  // namespace cairn::multibody
