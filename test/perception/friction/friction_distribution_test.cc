#include "cairn/perception/friction/friction_distribution.h"

#include <cmath>

#include <gtest/gtest.h>

#include "expect_throws.h"

namespace cairn::perception {
namespace {

// Trapezoidal integral of the pdf, to check the CDF, mean and variance against an independent computation.
struct Moments {
  double mass, mean, variance;
};
Moments Integrate(const FrictionDistribution& f, double lo, double hi, int n = 200000) {
  double mass = 0, first = 0, second = 0;
  const double h = (hi - lo) / n;
  for (int i = 0; i <= n; ++i) {
    const double x = lo + i * h;
    const double w = (i == 0 || i == n) ? 0.5 : 1.0;
    const double p = f.Pdf(x) * w * h;
    mass += p;
    first += p * x;
    second += p * x * x;
  }
  return {mass, first / mass, second / mass - (first / mass) * (first / mass)};
}

TEST(FrictionDistributionTest, StandardNormalQuantileInvertsTheCdf) {
  for (double p : {1e-12, 1e-6, 0.01, 0.05, 0.3, 0.5, 0.7, 0.95, 0.999999}) {
    EXPECT_NEAR(StandardNormalCdf(StandardNormalQuantile(p)), p, 1e-14 + 1e-12 * p) << p;
  }
  EXPECT_NEAR(StandardNormalQuantile(0.95), 1.6448536269514722, 1e-13);
  CAIRN_EXPECT_THROWS_WITH(StandardNormalQuantile(1.0), std::invalid_argument, "(0, 1)");
}

TEST(FrictionDistributionTest, MomentsAndCdfAgreeWithNumericalIntegration) {
  const FrictionDistribution distributions[] = {
      FrictionDistribution::Normal(0.74, 0.12),
      FrictionDistribution::TruncatedNormal(0.2, 0.3),
      FrictionDistribution::GeneralizedExtremeValue(0.6, 0.1, -0.2),
      FrictionDistribution::GeneralizedExtremeValue(0.6, 0.1, 0.0),
      FrictionDistribution::GeneralizedExtremeValue(0.6, 0.1, 0.2),
  };
  for (const FrictionDistribution& f : distributions) {
    // The GEV with shape 0.2 has a slowly decaying upper tail: integrate far enough for its variance.
    const Moments m = Integrate(f, -1.0, 60.0, 2000000);
    EXPECT_NEAR(m.mass, 1.0, 2e-4) << f.kind_name();
    EXPECT_NEAR(m.mean, f.Mean(), 2e-4) << f.kind_name();
    EXPECT_NEAR(m.variance, f.Variance(), 2e-4) << f.kind_name();
    for (double p : {0.05, 0.5, 0.9}) EXPECT_NEAR(f.Cdf(f.Quantile(p)), p, 1e-12) << f.kind_name();
  }
}

TEST(FrictionDistributionTest, TruncatedNormalHasNoMassBelowZeroAndNotWalkableIsAtZero) {
  const auto truncated = FrictionDistribution::TruncatedNormal(0.1, 0.2);
  EXPECT_EQ(truncated.Cdf(-0.01), 0.0);
  EXPECT_GT(truncated.Quantile(0.01), 0.0);
  const auto water = FrictionDistribution::NotWalkable();
  EXPECT_FALSE(water.walkable());
  EXPECT_EQ(water.Cdf(0.0), 1.0);
  EXPECT_EQ(water.Quantile(0.5), 0.0);
}

TEST(FrictionDistributionTest, RejectsBadParameters) {
  CAIRN_EXPECT_THROWS_WITH(FrictionDistribution::Normal(0.5, -0.1), std::invalid_argument,
                           "standard deviation must be >= 0; got -0.1");
  CAIRN_EXPECT_THROWS_WITH(FrictionDistribution::GeneralizedExtremeValue(0.5, 0.0, 0.1), std::invalid_argument,
                           "GEV scale must be > 0");
  CAIRN_EXPECT_THROWS_WITH(FrictionDistribution::TruncatedNormal(-5.0, 0.1), std::invalid_argument,
                           "no mass on [0, inf)");
  CAIRN_EXPECT_THROWS_WITH(FrictionDistribution::Normal(std::nan(""), 0.1), std::invalid_argument, "finite");
}

}  // namespace
}  // namespace cairn::perception
