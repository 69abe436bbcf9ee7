#include "cairn/perception/terrain/collapsibility_estimator.h"

#include <random>

#include <gtest/gtest.h>

#include "expect_throws.h"

namespace cairn::perception {
namespace {

TEST(CollapsibilityEstimatorTest, EquationFive) {
  EXPECT_DOUBLE_EQ(CollapsibilityEstimator::FromForce(0.0, 100.0), 1.0);    // a covered hole
  EXPECT_DOUBLE_EQ(CollapsibilityEstimator::FromForce(30.0, 100.0), 0.7);   // soft but walkable
  EXPECT_DOUBLE_EQ(CollapsibilityEstimator::FromForce(100.0, 100.0), 0.0);  // hard
  EXPECT_DOUBLE_EQ(CollapsibilityEstimator::FromForce(140.0, 100.0), 0.0);
  EXPECT_DOUBLE_EQ(CollapsibilityEstimator::FromForce(-5.0, 100.0), 1.0);   // truncated to [0, 1]
}

TEST(CollapsibilityEstimatorTest, SlidingWindowAveragesNoise) {
  CollapsibilityEstimator estimator(CollapsibilityEstimator::Options{100.0, 50});
  std::mt19937 rng(11);
  std::normal_distribution<double> noise(0.0, 5.0);
  for (int k = 0; k < 200; ++k) estimator.AddSample(k < 100 ? 90.0 + noise(rng) : 40.0 + noise(rng));
  EXPECT_EQ(estimator.num_samples(), 50);
  // Only the last 50 samples (the 40 N phase) count.
  EXPECT_NEAR(estimator.AverageForce(), 40.0, 3.0 * 5.0 / std::sqrt(50.0));
  EXPECT_NEAR(estimator.Collapsibility(), 0.6, 0.03);
  estimator.Reset();
  CAIRN_EXPECT_THROWS_WITH(estimator.Collapsibility(), std::logic_error, "no force sample yet");
  CAIRN_EXPECT_THROWS_WITH(estimator.AddSample(NAN), std::invalid_argument, "force sample nan N");
  CAIRN_EXPECT_THROWS_WITH(CollapsibilityEstimator(CollapsibilityEstimator::Options{0.0, 5}), std::invalid_argument,
                           "hard_force 0 N");
}

}  // namespace
}  // namespace cairn::perception
