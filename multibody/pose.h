#pragma once

/// @file
/// Rigid transforms and the spatial-vector actions the multibody algorithms are built on.
///
/// Spatial vectors are stacked angular first: a motion (twist) is [ω; v] and a force (wrench) is [n; f],
/// the convention of Featherstone and DART. They are fixed-size Eigen types so that no algorithm allocates.

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace cairn::multibody {

/// A 6-vector of a spatial motion [ω; v] or a spatial force [n; f].
using Vector6d = Eigen::Matrix<double, 6, 1>;
/// A 6x6 spatial matrix (inertias, spatial transforms in matrix form).
using Matrix6d = Eigen::Matrix<double, 6, 6>;

/// Returns the skew-symmetric matrix [a]x with [a]x b = a x b.
inline Eigen::Matrix3d Skew(const Eigen::Vector3d& a) {
  Eigen::Matrix3d s;
  s << 0.0, -a.z(), a.y(), a.z(), 0.0, -a.x(), -a.y(), a.x(), 0.0;
  return s;
}

/// Spatial cross product for motions, m1 x m2 (the derivative of m2 carried by a frame moving with m1).
inline Vector6d CrossMotion(const Vector6d& m1, const Vector6d& m2) {
  Vector6d out;
  const Eigen::Vector3d w = m1.head<3>();
  const Eigen::Vector3d v = m1.tail<3>();
  out.head<3>() = w.cross(m2.head<3>());
  out.tail<3>() = w.cross(m2.tail<3>()) + v.cross(m2.head<3>());
  return out;
}

/// Spatial cross product of a motion with a force, m x* f (the dual of CrossMotion).
inline Vector6d CrossForce(const Vector6d& m, const Vector6d& f) {
  Vector6d out;
  const Eigen::Vector3d w = m.head<3>();
  const Eigen::Vector3d v = m.tail<3>();
  out.head<3>() = w.cross(f.head<3>()) + v.cross(f.tail<3>());
  out.tail<3>() = w.cross(f.tail<3>());
  return out;
}

/// A rigid transform X_AB: the pose of frame B in frame A, stored as a rotation R_AB and the position p_AB of
/// B's origin in A. Kept as a 3x3 rotation and a 3-vector (not a 4x4 matrix) because the algorithms compose
/// thousands of them per call.
class Pose {
 public:
  /// The identity transform.
  Pose() : rotation_(Eigen::Matrix3d::Identity()), translation_(Eigen::Vector3d::Zero()) {}

  /// A transform from its rotation R_AB (assumed orthonormal) and translation p_AB.
  Pose(const Eigen::Matrix3d& rotation, const Eigen::Vector3d& translation)
      : rotation_(rotation), translation_(translation) {}

  /// Converts from an Eigen isometry.
  explicit Pose(const Eigen::Isometry3d& isometry)
      : rotation_(isometry.linear()), translation_(isometry.translation()) {}

  /// Rotation R_AB.
  const Eigen::Matrix3d& rotation() const { return rotation_; }
  /// Translation p_AB.
  const Eigen::Vector3d& translation() const { return translation_; }

  /// Composition X_AC = X_AB * X_BC.
  Pose operator*(const Pose& X_BC) const {
    return Pose(rotation_ * X_BC.rotation_, rotation_ * X_BC.translation_ + translation_);
  }

  /// Maps a point p_B (measured in B) to p_A.
  Eigen::Vector3d operator*(const Eigen::Vector3d& p_B) const { return rotation_ * p_B + translation_; }

  /// The inverse X_BA.
  Pose Inverse() const { return Pose(rotation_.transpose(), -(rotation_.transpose() * translation_)); }

  /// Re-expresses a motion given in B (about B's origin) in A (about A's origin).
  Vector6d ActMotion(const Vector6d& m_B) const {
    Vector6d m_A;
    m_A.head<3>() = rotation_ * m_B.head<3>();
    m_A.tail<3>() = rotation_ * m_B.tail<3>() + translation_.cross(m_A.head<3>());
    return m_A;
  }

  /// Re-expresses a motion given in A in B (the action of the inverse transform, without forming it).
  Vector6d InverseActMotion(const Vector6d& m_A) const {
    Vector6d m_B;
    m_B.head<3>() = rotation_.transpose() * m_A.head<3>();
    m_B.tail<3>() = rotation_.transpose() * (m_A.tail<3>() - translation_.cross(m_A.head<3>()));
    return m_B;
  }

  /// Re-expresses a force given in B (moment about B's origin) in A (moment about A's origin).
  Vector6d ActForce(const Vector6d& f_B) const {
    Vector6d f_A;
    f_A.tail<3>() = rotation_ * f_B.tail<3>();
    f_A.head<3>() = rotation_ * f_B.head<3>() + translation_.cross(f_A.tail<3>());
    return f_A;
  }

  /// Re-expresses a force given in A in B.
  Vector6d InverseActForce(const Vector6d& f_A) const {
    Vector6d f_B;
    f_B.tail<3>() = rotation_.transpose() * f_A.tail<3>();
    f_B.head<3>() = rotation_.transpose() * (f_A.head<3>() - translation_.cross(f_A.tail<3>()));
    return f_B;
  }

  /// The transform as an Eigen isometry (for callers that want Eigen's geometry module).
  Eigen::Isometry3d ToIsometry() const {
    Eigen::Isometry3d out = Eigen::Isometry3d::Identity();
    out.linear() = rotation_;
    out.translation() = translation_;
    return out;
  }

  /// True if rotation and translation agree with `other` to `tolerance` (max-abs).
  bool IsApprox(const Pose& other, double tolerance) const {
    return (rotation_ - other.rotation_).cwiseAbs().maxCoeff() <= tolerance &&
           (translation_ - other.translation_).cwiseAbs().maxCoeff() <= tolerance;
  }

 private:
  Eigen::Matrix3d rotation_;
  Eigen::Vector3d translation_;
};

}  // namespace cairn::multibody
