#pragma once

#include <Eigen/Core>

namespace cairn::planning {

/// A COM motion of the cart-table model and its ZMP.
struct CartTableMotion {
  Eigen::VectorXd position;      ///< x_k, m
  Eigen::VectorXd velocity;      ///< x'_k, m/s
  Eigen::VectorXd acceleration;  ///< x''_k, m/s^2
  Eigen::VectorXd zmp;           ///< p_k = x_k - (z_c / g) x''_k, m
};

/// ZMP preview control on the cart-table model (Kajita et al. 2003, in the integral form of Katayama et al.
/// 1985). One horizontal axis, sampled every dt: state x = [x, x', x''], input the jerk u,
///   x_k+1 = A x_k + B u_k,  A = [1 dt dt^2/2; 0 1 dt; 0 0 1],  B = [dt^3/6; dt^2/2; dt],
///   p_k = C x_k,  C = [1 0 -z_c/g].
/// The cost sum Q e_k^2 + R (u_k - u_k-1)^2 with e = p - p_ref on the augmented system
/// [e_k; x_k - x_k-1] (A~ = [1 CA; 0 A], B~ = [CB; B]) gives, with P the solution of its Riccati equation
/// (SolveDiscreteAlgebraicRiccati) and S = R + B~^T P B~, the gains
///   G_i = S^-1 B~^T P I~,  G_x = S^-1 B~^T P [CA; A],  A_c = A~ - B~ S^-1 B~^T P A~,
///   G_d(1) = -G_i,  G_d(j) = S^-1 B~^T X_j-1 with X_1 = -A_c^T P I~, X_j = A_c^T X_j-1,
/// and the control u_k = -G_i sum_i<=k e_i - G_x x_k - sum_j=1..N G_d(j) p_ref(k + j), N = preview / dt.
class CartTablePreviewController {
 public:
  /// Throws std::invalid_argument unless dt in (0, 0.1], com_height and gravity positive and finite, preview in
  /// [dt, 5] s (at most 50000 samples), q and r positive and finite.
  CartTablePreviewController(double dt, double com_height, double gravity = 9.81, double preview = 1.6,
                             double q = 1.0, double r = 1e-6);

  /// Runs the controller from rest at `start` along the reference ZMP (references beyond the end are the last
  /// value held). Throws std::invalid_argument for an empty or non-finite reference.
  CartTableMotion Track(const Eigen::VectorXd& zmp_reference, double start = 0.0) const;

  /// The cart-table ZMP p = x - (z_c / g) x'' of a COM motion (the C of the model).
  double zmp_gain() const { return com_height_ / gravity_; }
  double integral_gain() const { return gi_; }
  const Eigen::RowVector3d& state_gain() const { return gx_; }
  /// G_d(1..N).
  const Eigen::VectorXd& preview_gains() const { return gd_; }

 private:
  double dt_, com_height_, gravity_;
  Eigen::Matrix3d a_;
  Eigen::Vector3d b_;
  Eigen::RowVector3d c_;
  double gi_{0.0};
  Eigen::RowVector3d gx_;
  Eigen::VectorXd gd_;
};

}  // namespace cairn::planning
