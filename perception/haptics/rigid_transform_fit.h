#pragma once

/// @file
/// The closed-form least-squares rigid transform between corresponding points (seed 000, §3.2, eq. 5).

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace cairn::perception {

/// The transform M = X_AC with p_A ≈ M p_C and how well it fits.
struct RigidTransformFit {
  Eigen::Isometry3d X_AC{Eigen::Isometry3d::Identity()};
  /// sqrt(mean |p_A - M p_C|²) (m).
  double rms_residual{0.0};
  /// max |p_A - M p_C| (m).
  double max_residual{0.0};
};

/// argmin over rotations R and translations t of Σ |p_A - (R p_C + t)|² (eq. 5), by the SVD of the cross-covariance
/// of the centred point sets (Arun, Huang and Blostein; the sign of the smallest singular direction is flipped when
/// needed so that R is a rotation, not a reflection). Columns of the two matrices correspond.
/// Throws std::invalid_argument when the sizes differ, there are fewer than 3 points, a point is not finite, or
/// the points of C are (nearly) collinear so that the rotation is not determined.
RigidTransformFit FitRigidTransform(const Eigen::Matrix3Xd& p_C, const Eigen::Matrix3Xd& p_A);

}  // namespace cairn::perception
