#pragma once

#include <Eigen/Core>

#include <cairn/multibody/pose.h>

namespace cairn::multibody {

/// The spatial inertia of a rigid body, expressed in some frame B.
///
/// Stored as mass m, first moment h = m c (c: centre of mass in B) and the rotational inertia about B's origin
/// I_o. That parameterisation is linear: adding two inertias adds the parts, and a zero mass needs no special
/// case, which is what the composite-rigid-body pass wants.
class SpatialInertia {
 public:
  /// The zero inertia.
  SpatialInertia() : mass_(0.0), first_moment_(Eigen::Vector3d::Zero()), inertia_origin_(Eigen::Matrix3d::Zero()) {}

  /// From mass, centre of mass c (in B) and the rotational inertia about the centre of mass (B's axes).
  static SpatialInertia FromMassComInertia(double mass, const Eigen::Vector3d& com,
                                           const Eigen::Matrix3d& inertia_com) {
    SpatialInertia out;
    out.mass_ = mass;
    out.first_moment_ = mass * com;
    const Eigen::Matrix3d c = Skew(com);
    out.inertia_origin_ = inertia_com - mass * c * c;
    return out;
  }

  /// Mass.
  double mass() const { return mass_; }
  /// First moment of mass m c.
  const Eigen::Vector3d& first_moment() const { return first_moment_; }
  /// Rotational inertia about the origin of the frame the inertia is expressed in.
  const Eigen::Matrix3d& inertia_origin() const { return inertia_origin_; }

  /// Centre of mass; the origin for a massless body.
  Eigen::Vector3d com() const { return mass_ > 0.0 ? Eigen::Vector3d(first_moment_ / mass_) : Eigen::Vector3d::Zero(); }

  /// Rotational inertia about the centre of mass.
  Eigen::Matrix3d InertiaAboutCom() const {
    if (mass_ <= 0.0) return inertia_origin_;
    const Eigen::Matrix3d c = Skew(com());
    return inertia_origin_ + mass_ * c * c;
  }

  /// The momentum I * v of a body moving with twist v (both in the same frame).
  Vector6d Apply(const Vector6d& v) const {
    Vector6d f;
    const Eigen::Vector3d w = v.head<3>();
    const Eigen::Vector3d lin = v.tail<3>();
    f.head<3>() = inertia_origin_ * w + first_moment_.cross(lin);
    f.tail<3>() = mass_ * lin - first_moment_.cross(w);
    return f;
  }

  /// The same inertia expressed in A, given X_AB and this inertia expressed in B.
  SpatialInertia Transformed(const Pose& X_AB) const {
    SpatialInertia out;
    const Eigen::Matrix3d& R = X_AB.rotation();
    const Eigen::Vector3d& p = X_AB.translation();
    out.mass_ = mass_;
    const Eigen::Vector3d Rh = R * first_moment_;
    out.first_moment_ = Rh + mass_ * p;
    const Eigen::Matrix3d P = Skew(p);
    const Eigen::Matrix3d H = Skew(Rh);
    out.inertia_origin_ = R * inertia_origin_ * R.transpose() - (H * P + P * H) - mass_ * P * P;
    return out;
  }

  /// Adds another inertia expressed in the same frame.
  SpatialInertia& operator+=(const SpatialInertia& other) {
    mass_ += other.mass_;
    first_moment_ += other.first_moment_;
    inertia_origin_ += other.inertia_origin_;
    return *this;
  }

  /// The 6x6 matrix form (angular rows first).
  Matrix6d Matrix() const {
    Matrix6d M;
    const Eigen::Matrix3d H = Skew(first_moment_);
    M.topLeftCorner<3, 3>() = inertia_origin_;
    M.topRightCorner<3, 3>() = H;
    M.bottomLeftCorner<3, 3>() = -H;
    M.bottomRightCorner<3, 3>() = mass_ * Eigen::Matrix3d::Identity();
    return M;
  }

 private:
  double mass_;
  Eigen::Vector3d first_moment_;
  Eigen::Matrix3d inertia_origin_;
};

}  // namespace cairn::multibody
