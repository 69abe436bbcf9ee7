#include "cairn/perception/haptics/rigid_transform_fit.h"

#include <stdexcept>

#include "expect_throws.h"

namespace cairn::perception {
namespace {

Eigen::Isometry3d KnownTransform() {
  Eigen::Isometry3d X = Eigen::Isometry3d::Identity();
  X.linear() = Eigen::AngleAxisd(0.3, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  X.translation() = Eigen::Vector3d(0.1, -0.25, 0.05);
  return X;
}

TEST(RigidTransformFitTest, RecoversAKnownTransformExactly) {
  Eigen::Matrix3Xd p_A(3, 5);
  p_A << -0.3, -0.3, 0.0, 0.1, -0.2, 0.1, 0.2, 0.0, 0.1, 0.1, 0.6, 0.6, 0.8, 0.8, 0.8;  // Table 1
  const Eigen::Isometry3d X_AC = KnownTransform();
  const Eigen::Matrix3Xd p_C = X_AC.inverse() * p_A;
  const RigidTransformFit fit = FitRigidTransform(p_C, p_A);
  EXPECT_TRUE(fit.X_AC.isApprox(X_AC, 1e-12));
  EXPECT_LT(fit.rms_residual, 1e-12);
  EXPECT_NEAR(fit.X_AC.linear().determinant(), 1.0, 1e-12);
}

TEST(RigidTransformFitTest, CoplanarPointsGiveARotationNotAReflection) {
  Eigen::Matrix3Xd p_C(3, 4);
  p_C << 0, 1, 0, 1, 0, 0, 1, 1, 0, 0, 0, 0;
  const Eigen::Isometry3d X_AC = KnownTransform();
  const RigidTransformFit fit = FitRigidTransform(p_C, X_AC * p_C);
  EXPECT_NEAR(fit.X_AC.linear().determinant(), 1.0, 1e-12);
  EXPECT_TRUE(fit.X_AC.isApprox(X_AC, 1e-12));
}

TEST(RigidTransformFitTest, ResidualOfAPerturbedPointByHand) {
  // Three points, the translation-only fit of a perturbation along z of one of them: the fit splits it.
  Eigen::Matrix3Xd p_C(3, 4);
  p_C << 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1;
  Eigen::Matrix3Xd p_A = p_C;
  const RigidTransformFit exact = FitRigidTransform(p_C, p_A);
  EXPECT_LT(exact.max_residual, 1e-12);
  p_A(0, 0) += 0.004;  // one point 4 mm off: least squares leaves a residual > 0 and < 4 mm
  const RigidTransformFit off = FitRigidTransform(p_C, p_A);
  EXPECT_GT(off.rms_residual, 1e-4);
  EXPECT_LT(off.max_residual, 0.004);
}

TEST(RigidTransformFitTest, BadInputNamesTheValue) {
  CAIRN_EXPECT_THROWS_WITH(FitRigidTransform(Eigen::Matrix3Xd::Zero(3, 3), Eigen::Matrix3Xd::Zero(3, 4)),
                           std::invalid_argument, "3 sensor points but 4 antenna points");
  CAIRN_EXPECT_THROWS_WITH(FitRigidTransform(Eigen::Matrix3Xd::Zero(3, 2), Eigen::Matrix3Xd::Zero(3, 2)),
                           std::invalid_argument, "at least 3 correspondences; got 2");
  Eigen::Matrix3Xd line(3, 3);
  line << 0, 1, 2, 0, 0, 0, 0, 0, 0;
  CAIRN_EXPECT_THROWS_WITH(FitRigidTransform(line, line), std::invalid_argument, "collinear");
}

}  // namespace
}  // namespace cairn::perception
