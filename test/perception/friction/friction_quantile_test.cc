#include "cairn/perception/friction/friction_quantile.h"

#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "expect_throws.h"

namespace cairn::perception {
namespace {

Eigen::VectorXd OneHot(const MaterialRegistry& registry, const std::string& label) {
  Eigen::VectorXd p = Eigen::VectorXd::Zero(registry.size());
  p[registry.IndexOf(label)] = 1.0;
  return p;
}

TEST(FrictionQuantileTest, SingleMaterialQuantileIsTheNormalQuantile) {
  const auto registry = MaterialRegistry::ThesisTable33();
  const double expected = 0.74 - 0.12 * 1.6448536269514722;  // asphalt, eta = 0.95
  const Eigen::VectorXd asphalt = OneHot(registry, "asphalt");
  EXPECT_NEAR(FrictionQuantile(registry, asphalt, 0.95, QuantileMethod::kExact), expected, 1e-4);
  EXPECT_NEAR(FrictionQuantile(registry, asphalt, 0.95, QuantileMethod::kGaussian), expected, 1e-12);
  const double searched = FrictionQuantile(registry, asphalt, 0.95, QuantileMethod::kSearch, 0.02);
  EXPECT_LE(searched, expected);
  EXPECT_GT(searched, expected - 0.02);
  // Water is not walkable: all mass at zero.
  EXPECT_EQ(FrictionQuantile(registry, OneHot(registry, "water"), 0.95, QuantileMethod::kExact), 0.0);
}

TEST(FrictionQuantileTest, MixtureQuantileSolvesTheMixtureCdf) {
  const auto registry = MaterialRegistry::ThesisTable33();
  Eigen::VectorXd p = Eigen::VectorXd::Zero(registry.size());
  p[registry.IndexOf("ceramic")] = 0.6;
  p[registry.IndexOf("wood")] = 0.3;
  p[registry.IndexOf("water")] = 0.1;
  const double q = FrictionQuantile(registry, p, 0.8, QuantileMethod::kExact, 1e-6);
  EXPECT_NEAR(MixtureCdf(registry, p, q), 0.2, 1e-5);
  // With 10% water the 0.95 bound collapses to zero: the robot must not trust this pixel.
  EXPECT_EQ(FrictionQuantile(registry, p, 0.95, QuantileMethod::kExact), 0.0);
}

TEST(FrictionQuantileTest, SearchAndGaussianErrorsAgainstExact) {
  // Random mixtures over the walkable labels: Algorithm 1's error is below its step; the Gaussian moment
  // approximation is cruder (the thesis reports RMSE 0.1 on real segmentations).
  const auto registry = MaterialRegistry::ThesisTable33();
  std::mt19937 random(7);
  std::gamma_distribution<double> gamma(0.3, 1.0);
  double worst_search = 0.0, gaussian_squared = 0.0;
  const int trials = 200;
  for (int t = 0; t < trials; ++t) {
    Eigen::VectorXd p = Eigen::VectorXd::Zero(registry.size());
    for (int i = 0; i < 8; ++i) p[i] = gamma(random) + 1e-9;
    p /= p.sum();
    const double exact = FrictionQuantile(registry, p, 0.95, QuantileMethod::kExact, 1e-7);
    const double search = FrictionQuantile(registry, p, 0.95, QuantileMethod::kSearch, 0.02);
    const double gaussian = FrictionQuantile(registry, p, 0.95, QuantileMethod::kGaussian);
    worst_search = std::max(worst_search, exact - search);
    EXPECT_GE(exact - search, -1e-6);
    gaussian_squared += (gaussian - exact) * (gaussian - exact);
  }
  EXPECT_LT(worst_search, 0.02);
  const double gaussian_rmse = std::sqrt(gaussian_squared / trials);
  EXPECT_GT(gaussian_rmse, 0.005);
  EXPECT_LT(gaussian_rmse, 0.2);
}

TEST(FrictionQuantileTest, QuantileImageValidatesEveryPixel) {
  const auto registry = MaterialRegistry::ThesisTable33();
  Eigen::MatrixXd pixels = Eigen::MatrixXd::Zero(3, registry.size());
  pixels(0, 0) = 1.0;
  pixels(1, 4) = 1.0;
  pixels(2, 4) = 0.5;
  const Eigen::VectorXd ok = FrictionQuantiles(registry, pixels.topRows(2), 0.95, QuantileMethod::kExact);
  EXPECT_NEAR(ok[1], 0.97 - 0.05 * 1.6448536269514722, 1e-4);
  CAIRN_EXPECT_THROWS_WITH(FrictionQuantiles(registry, pixels, 0.95, QuantileMethod::kExact), std::invalid_argument,
                           "Pixel 2", "sum to 0.5", "normalise");
  CAIRN_EXPECT_THROWS_WITH(FrictionQuantile(registry, pixels.row(0).transpose(), 1.0, QuantileMethod::kExact),
                           std::invalid_argument, "eta", "(0, 1); got 1");
  CAIRN_EXPECT_THROWS_WITH(FrictionQuantile(registry, Eigen::VectorXd::Ones(3), 0.9, QuantileMethod::kExact),
                           std::invalid_argument, "3 entries but the registry has 14 labels");
  // Steps that would take 1e302 iterations (search) or never end (bisection below the doubles' resolution).
  CAIRN_EXPECT_THROWS_WITH(
      FrictionQuantile(registry, pixels.row(0).transpose(), 0.95, QuantileMethod::kSearch, 1e-300),
      std::invalid_argument, "search step 1e-300 is below 0.0001");
  EXPECT_NEAR(FrictionQuantile(registry, pixels.row(0).transpose(), 0.95, QuantileMethod::kExact, 1e-300),
              0.74 - 0.12 * 1.6448536269514722, 1e-9);
}

}  // namespace
}  // namespace cairn::perception
