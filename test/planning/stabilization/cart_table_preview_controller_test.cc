// Kajita's preview control on the cart-table model, and the Riccati solver under it.
#include <gtest/gtest.h>

#include <cmath>

#include <Eigen/LU>

#include <cairn/planning/stabilization/cart_table_preview_controller.h>
#include <cairn/planning/stabilization/discrete_riccati.h>

#include "expect_throws.h"

namespace cairn::planning {
namespace {

TEST(DiscreteRiccatiTest, ScalarEquationHasTheClosedFormRoot) {
  // x+ = a x + b u, cost q x^2 + r u^2: p = q + a^2 p - a^2 b^2 p^2 / (r + b^2 p), i.e. with a = 2, b = q = r = 1
  // p^2 - 4 p - 1 = 0 and p = 2 + sqrt(5).
  const Eigen::MatrixXd p = SolveDiscreteAlgebraicRiccati(Eigen::MatrixXd::Constant(1, 1, 2.0),
                                                          Eigen::MatrixXd::Ones(1, 1), Eigen::MatrixXd::Ones(1, 1),
                                                          Eigen::MatrixXd::Ones(1, 1));
  EXPECT_NEAR(p(0, 0), 2.0 + std::sqrt(5.0), 1e-10);
}

TEST(DiscreteRiccatiTest, SatisfiesTheEquationForADoubleIntegrator) {
  Eigen::MatrixXd a(2, 2), b(2, 1);
  a << 1.0, 0.01, 0.0, 1.0;
  b << 0.00005, 0.01;
  const Eigen::MatrixXd q = Eigen::MatrixXd::Identity(2, 2), r = Eigen::MatrixXd::Constant(1, 1, 1e-3);
  const Eigen::MatrixXd p = SolveDiscreteAlgebraicRiccati(a, b, q, r);
  const Eigen::MatrixXd residual =
      a.transpose() * p * a - a.transpose() * p * b * (r + b.transpose() * p * b).inverse() * b.transpose() * p * a +
      q - p;
  EXPECT_LT(residual.norm(), 1e-8 * p.norm());
}

TEST(DiscreteRiccatiTest, RejectsBadMatrices) {
  const Eigen::MatrixXd one = Eigen::MatrixXd::Ones(1, 1);
  CAIRN_EXPECT_THROWS_WITH(SolveDiscreteAlgebraicRiccati(Eigen::MatrixXd::Ones(2, 2), one, one, one),
                           std::invalid_argument, "sizes do not match");
  CAIRN_EXPECT_THROWS_WITH(SolveDiscreteAlgebraicRiccati(one, one, one, Eigen::MatrixXd::Zero(1, 1)),
                           std::invalid_argument, "R must be symmetric positive definite");
  CAIRN_EXPECT_THROWS_WITH(SolveDiscreteAlgebraicRiccati(one, one, -one, one), std::invalid_argument,
                           "Q must be symmetric positive semidefinite");
  // x+ = 2 x with no input cannot be stabilised.
  CAIRN_EXPECT_THROWS_WITH(SolveDiscreteAlgebraicRiccati(2.0 * one, Eigen::MatrixXd::Zero(1, 1), one, one),
                           std::runtime_error, "did not converge");
}

TEST(CartTablePreviewControllerTest, TracksAStepOfTheZmpWithPreview) {
  // Kajita's defaults: 5 ms, z_c = 0.8 m, 1.6 s preview, Q = 1, R = 1e-6; the reference steps 0.1 m at 2 s.
  const double dt = 0.005;
  const CartTablePreviewController controller(dt, 0.8, 9.81, 1.6, 1.0, 1e-6);
  Eigen::VectorXd reference = Eigen::VectorXd::Zero(1200);
  reference.tail(800).setConstant(0.1);
  const CartTableMotion motion = controller.Track(reference);
  // Settled well before and after the step, within a millimetre.
  EXPECT_NEAR(motion.zmp[200], 0.0, 1e-3);
  EXPECT_NEAR(motion.zmp[1199], 0.1, 1e-3);
  EXPECT_NEAR(motion.position[1199], 0.1, 2e-3);
  // The preview makes the COM move before the step (it cannot follow a step in the ZMP otherwise).
  EXPECT_GT(motion.position[399], 0.02);
  // The ZMP is the cart-table output of the motion.
  for (Eigen::Index k : {100, 400, 900}) {
    EXPECT_NEAR(motion.zmp[k], motion.position[k] - 0.8 / 9.81 * motion.acceleration[k], 1e-12);
  }
  double worst = 0.0;
  for (Eigen::Index k = 0; k < reference.size(); ++k) {
    if (std::abs(k - 400) > 60) worst = std::max(worst, std::abs(motion.zmp[k] - reference[k]));
  }
  EXPECT_LT(worst, 0.01);  // within 1 cm away from the 0.3 s around the step
}

TEST(CartTablePreviewControllerTest, RejectsBadParameters) {
  CAIRN_EXPECT_THROWS_WITH(CartTablePreviewController(0.0, 0.8), std::invalid_argument, "dt 0 s must be in (0, 0.1]");
  CAIRN_EXPECT_THROWS_WITH(CartTablePreviewController(0.005, -1.0), std::invalid_argument,
                           "com_height -1 m must be in (0, 100]");
  CAIRN_EXPECT_THROWS_WITH(CartTablePreviewController(0.005, 0.8, 9.81, 6.0), std::invalid_argument,
                           "preview 6 s must be in [dt = 0.005 s, 5 s]");
  const CartTablePreviewController controller(0.005, 0.8);
  CAIRN_EXPECT_THROWS_WITH(controller.Track(Eigen::VectorXd()), std::invalid_argument,
                           "the reference must be non-empty and finite");
}

}  // namespace
}  // namespace cairn::planning
