// The frequency-domain solution of the linearised ZMP equation, and the stabiliser factory.
#include <gtest/gtest.h>

#include <cmath>

#include <cairn/planning/stabilization/fft_zmp_stabilizer.h>
#include <cairn/planning/stabilization/preview_zmp_stabilizer.h>

#include "expect_throws.h"

namespace cairn::planning {
namespace {

// The cart-table ZMP change dx - (z_c/g) dx'' of offsets by central differences.
Eigen::VectorXd CartTableZmp(const Eigen::VectorXd& x, double dt, double z_c) {
  Eigen::VectorXd p = x;
  for (Eigen::Index k = 1; k + 1 < x.size(); ++k) p[k] = x[k] - z_c / 9.81 * (x[k + 1] - 2 * x[k] + x[k - 1]) / (dt * dt);
  return p;
}

TEST(FftZmpStabilizerTest, OffsetsSolveTheLinearisedZmpEquation) {
  // A smooth error pulse (2 cm, 0.3 s wide) in the middle of 4 s: the offsets' cart-table ZMP reproduces it.
  const double dt = 0.005, z_c = 0.75;
  Eigen::VectorXd error(800);
  for (Eigen::Index k = 0; k < error.size(); ++k) {
    const double t = dt * static_cast<double>(k) - 2.0;
    error[k] = 0.02 * std::exp(-t * t / (2.0 * 0.15 * 0.15));
  }
  const FftZmpStabilizer stabilizer(9.81, 2.0);
  const Eigen::VectorXd offsets = stabilizer.ComOffsets(error, dt, z_c);
  const Eigen::VectorXd p = CartTableZmp(offsets, dt, z_c);
  for (Eigen::Index k = 1; k + 1 < error.size(); ++k) EXPECT_NEAR(p[k], error[k], 2e-4) << k;
  // Non-causal: the COM leans before the pulse (the low-pass keeps it smaller than the error).
  EXPECT_GT(offsets[350], 0.0);
  EXPECT_LT(offsets.maxCoeff(), 0.02);
}

TEST(FftZmpStabilizerTest, PreviewOffsetsTrackTheErrorToo) {
  const double dt = 0.005, z_c = 0.75;
  Eigen::VectorXd error(800);
  for (Eigen::Index k = 0; k < error.size(); ++k) {
    const double t = dt * static_cast<double>(k) - 2.0;
    error[k] = 0.02 * std::exp(-t * t / (2.0 * 0.15 * 0.15));
  }
  const PreviewZmpStabilizer stabilizer;
  const Eigen::VectorXd p = CartTableZmp(stabilizer.ComOffsets(error, dt, z_c), dt, z_c);
  double worst = 0.0;
  for (Eigen::Index k = 1; k + 1 < error.size(); ++k) worst = std::max(worst, std::abs(p[k] - error[k]));
  EXPECT_LT(worst, 2e-3);
}

TEST(FftZmpStabilizerTest, FactoryChoosesByNameAndRejectsBadInput) {
  StabilizerOptions options;
  options.method = "fft";
  EXPECT_EQ(MakeZmpStabilizer(options)->name(), "fft");
  options.method = "preview";
  EXPECT_EQ(MakeZmpStabilizer(options)->name(), "preview");
  options.method = "none";
  CAIRN_EXPECT_THROWS_WITH(MakeZmpStabilizer(options), std::invalid_argument, "method 'none' has no stabiliser");
  options.method = "lqr";
  CAIRN_EXPECT_THROWS_WITH(MakeZmpStabilizer(options), std::invalid_argument,
                           "method 'lqr' is unknown; use fft, preview or none");
  const FftZmpStabilizer stabilizer;
  CAIRN_EXPECT_THROWS_WITH(stabilizer.ComOffsets(Eigen::VectorXd::Zero(4), 0.005, 0.0), std::invalid_argument,
                           "COM height 0 m must be positive and finite");
  CAIRN_EXPECT_THROWS_WITH(FftZmpStabilizer(9.81, 20.0), std::invalid_argument, "padding 20 s must be in [0, 10]");
}

}  // namespace
}  // namespace cairn::planning
