#include "cairn/planning/locomotion/walking_pattern_generator.h"

#include <cmath>

#include <gtest/gtest.h>

#include "expect_throws.h"

namespace cairn::planning {
namespace {

constexpr double kG = 9.81;

WalkingPattern Fine(const StepDisplacement& d, const StepParameters& p) {
  WalkingPatternOptions options;
  options.samples_per_phase = 2001;
  return GenerateWalkingPattern(d, p, kG, options);
}

// Central differences of column-wise samples inside one phase [first, last].
Eigen::Vector3d Derivative(const Eigen::Matrix3Xd& x, const Eigen::VectorXd& t, int k) {
  return (x.col(k + 1) - x.col(k - 1)) / (t[k + 1] - t[k - 1]);
}

class PatternTest : public ::testing::TestWithParam<StepDisplacement> {};

// The sampled COM obeys its own derivatives and the cart-table ZMP equation, recomputed from finite
// differences of the positions alone: p = x - (z - z_p) x'' / (z'' + g).
TEST_P(PatternTest, SatisfiesTheCartTableEquation) {
  const StepDisplacement d = GetParam();
  const StepParameters p{0.4, 1.0, 0.74};
  const WalkingPattern pattern = Fine(d, p);
  const int n = 2001;
  double worst_velocity = 0.0, worst_acceleration = 0.0, worst_zmp = 0.0;
  for (int phase = 0; phase < 2; ++phase) {
    for (int k = phase * n + 1; k < (phase + 1) * n - 1; ++k) {
      worst_velocity = std::max(worst_velocity,
                                (Derivative(pattern.com, pattern.time, k) - pattern.com_velocity.col(k)).norm());
      const Eigen::Vector3d a = Derivative(pattern.com_velocity, pattern.time, k);
      worst_acceleration = std::max(worst_acceleration, (a - pattern.com_acceleration.col(k)).norm());
      const double h_fd = pattern.com(2, k) - pattern.zmp(2, k);
      const Eigen::Vector2d zmp = pattern.com.col(k).head<2>() - h_fd * a.head<2>() / (a.z() + kG);
      worst_zmp = std::max(worst_zmp, (zmp - pattern.zmp.col(k).head<2>()).norm());
    }
  }
  EXPECT_LT(worst_velocity, 1e-6);
  EXPECT_LT(worst_acceleration, 1e-5);
  EXPECT_LT(worst_zmp, 1e-6);
  // The COM rides h above the plane through the footholds, and the ZMP on it.
  for (int k = 0; k < 2 * n; k += 97) {
    EXPECT_NEAR(pattern.com(2, k), p.com_height + pattern.slope * pattern.com(0, k), 1e-12);
    EXPECT_NEAR(pattern.zmp(2, k), pattern.slope * pattern.zmp(0, k), 1e-12);
  }
}

// The end of the step, moved to the next foothold and mirrored, is the start of the step.
TEST_P(PatternTest, IsPeriodic) {
  const StepDisplacement d = GetParam();
  const WalkingPattern pattern = GenerateWalkingPattern(d, StepParameters{0.2, 0.9, 0.76}, kG);
  const int last = static_cast<int>(pattern.time.size()) - 1;
  const Eigen::Vector3d mirror(1.0, -1.0, 1.0);
  const Eigen::Vector3d end = (pattern.com.col(last) - Eigen::Vector3d(d.dx, d.dy, d.dz)).cwiseProduct(mirror);
  EXPECT_LT((end - pattern.com.col(0)).norm(), 1e-9);
  EXPECT_LT((pattern.com_velocity.col(last).cwiseProduct(mirror) - pattern.com_velocity.col(0)).norm(), 1e-9);
  EXPECT_NEAR(pattern.time[last], 1.1, 1e-12);
  // ZMP reference: previous sole centre -> stance sole centre in double support, then the stance centre.
  EXPECT_LT((pattern.zmp.col(0) - pattern.previous_foot.position).norm(), 1e-12);
  EXPECT_LT(pattern.zmp.col(last).norm(), 1e-12);
  EXPECT_EQ(pattern.phase.front(), ContactPhase::kDoubleSupport);
  EXPECT_EQ(pattern.phase.back(), ContactPhase::kSingleSupport);
  EXPECT_DOUBLE_EQ(pattern.stance_load_fraction[0], 0.0);
  EXPECT_DOUBLE_EQ(pattern.stance_load_fraction[last], 1.0);
  EXPECT_EQ(pattern.previous_foot.position, Eigen::Vector3d(-d.dx, d.dy, -d.dz));
  EXPECT_EQ(pattern.next_foot.yaw, d.dtheta);
}

INSTANTIATE_TEST_SUITE_P(Steps, PatternTest,
                         ::testing::Values(StepDisplacement{0.0, 0.2, 0.0, 0.0}, StepDisplacement{0.25, 0.2, 0.0, 0.0},
                                           StepDisplacement{0.3, 0.25, 0.0, 0.5}, StepDisplacement{0.2, 0.2, 0.1, 0.0},
                                           StepDisplacement{0.25, 0.18, -0.12, 0.2}));

TEST(WalkingPatternGeneratorTest, SwingIsSymmetricOnLevelGround) {
  // In a symmetric periodic gait the COM passes the stance foot mid-swing, so x is odd about that instant.
  const WalkingPattern pattern = GenerateWalkingPattern({0.3, 0.2, 0.0, 0.0}, {0.2, 1.0, 0.76}, kG);
  const int n = 16;
  for (int k = 0; k < n; ++k) {
    EXPECT_NEAR(pattern.com(0, n + k), -pattern.com(0, 2 * n - 1 - k), 1e-9);
    EXPECT_NEAR(pattern.com(1, n + k), pattern.com(1, 2 * n - 1 - k), 1e-9);
  }
}

TEST(WalkingPatternGeneratorTest, ReusesBuffers) {
  WalkingPattern pattern;
  GenerateWalkingPattern({0.2, 0.2, 0.0, 0.0}, {0.3, 0.9, 0.76}, kG, WalkingPatternOptions(), pattern);
  const double* data = pattern.com.data();
  GenerateWalkingPattern({0.1, 0.2, 0.05, 0.0}, {0.5, 1.2, 0.7}, kG, WalkingPatternOptions(), pattern);
  EXPECT_EQ(pattern.com.data(), data);
}

TEST(WalkingPatternGeneratorTest, RejectsBadInput) {
  CAIRN_EXPECT_THROWS_WITH(GenerateWalkingPattern({0.2, 0.2, 0.0, 0.0}, {-0.1, 0.9, 0.76}, kG), std::invalid_argument,
                           "t_ds, t_sw and com_height must be positive");
  CAIRN_EXPECT_THROWS_WITH(GenerateWalkingPattern({NAN, 0.2, 0.0, 0.0}, {0.1, 0.9, 0.76}, kG), std::invalid_argument,
                           "dx is not finite");
  CAIRN_EXPECT_THROWS_WITH(GenerateWalkingPattern({0.0, 0.2, 0.1, 0.0}, {0.1, 0.9, 0.76}, kG), std::invalid_argument,
                           "no periodic gait");
  WalkingPatternOptions options;
  options.samples_per_phase = 1;
  CAIRN_EXPECT_THROWS_WITH(GenerateWalkingPattern({0.2, 0.2, 0.0, 0.0}, {0.1, 0.9, 0.76}, kG, options),
                           std::invalid_argument, "samples_per_phase must be >= 2");
}

}  // namespace
}  // namespace cairn::planning
