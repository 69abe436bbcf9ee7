#pragma once

/// @file
/// Per-joint kinematics shared by the algorithms: joint transforms and motion subspaces. The algorithms switch
/// on JointType (no virtual calls in the inner loops). Internal to multibody/, but header-only so that it
/// inlines into each algorithm.

#include <cmath>
#include <stdexcept>
#include <string>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <cairn/common/number_text.h>
#include <cairn/multibody/joint.h>
#include <cairn/multibody/pose.h>

namespace cairn::multibody::internal {

/// Rotation by `angle` about the unit `axis` (Rodrigues).
inline Eigen::Matrix3d AxisAngleRotation(const Eigen::Vector3d& axis, double angle) {
  const double s = std::sin(angle);
  const double c = std::cos(angle);
  const Eigen::Matrix3d K = Skew(axis);
  return Eigen::Matrix3d::Identity() + s * K + (1.0 - c) * (K * K);
}

/// Rotation of a floating joint's quaternion (w, x, y, z at q[0..3]). Accepts quaternions within 1e-3 of unit
/// length (integrators drift slightly) and uses the rotation they represent; anything else is an error.
inline Eigen::Matrix3d QuaternionRotation(const double* quaternion_wxyz, const std::string& joint_name) {
  const Eigen::Quaterniond quat(quaternion_wxyz[0], quaternion_wxyz[1], quaternion_wxyz[2], quaternion_wxyz[3]);
  const double norm = quat.norm();
  if (!(std::abs(norm - 1.0) <= 1e-3)) {
    throw std::invalid_argument("floating joint '" + joint_name + "': quaternion has norm " + cairn::FormatShort(norm) +
                                ", expected a unit quaternion (w, x, y, z); normalize it (see NormalizeConfiguration)");
  }
  return Eigen::Quaterniond(quat.w() / norm, quat.x() / norm, quat.y() / norm, quat.z() / norm).toRotationMatrix();
}

/// X_PC: pose of the child body in the parent body at joint coordinates q (pointer to the joint's first
/// coordinate).
inline Pose JointTransform(const Joint& joint, const double* q) {
  switch (joint.type) {
    case JointType::kFixed:
      return joint.X_PJ;
    case JointType::kRevolute: {
      if (joint.axis_index < 0) {
        return Pose(joint.X_PJ.rotation() * AxisAngleRotation(joint.axis, q[0]), joint.X_PJ.translation());
      }
      // Rotation about a coordinate axis: only the two other columns of R_PJ mix.
      const double angle = joint.axis_sign * q[0];
      const double s = std::sin(angle);
      const double c = std::cos(angle);
      const int a = joint.axis_index;
      const int b = (a + 1) % 3;
      const int d = (a + 2) % 3;
      Eigen::Matrix3d R;
      if (joint.origin_rotation_is_identity) {
        R.setZero();
        R(a, a) = 1.0;
        R(b, b) = c;
        R(d, b) = s;
        R(b, d) = -s;
        R(d, d) = c;
      } else {
        const Eigen::Matrix3d& R0 = joint.X_PJ.rotation();
        R.col(a) = R0.col(a);
        R.col(b) = c * R0.col(b) + s * R0.col(d);
        R.col(d) = c * R0.col(d) - s * R0.col(b);
      }
      return Pose(R, joint.X_PJ.translation());
    }
    case JointType::kPrismatic:
      return Pose(joint.X_PJ.rotation(), joint.X_PJ.translation() + joint.X_PJ.rotation() * (joint.axis * q[0]));
    case JointType::kFloating:
      return joint.X_PJ * Pose(QuaternionRotation(q + 3, joint.name), Eigen::Vector3d(q[0], q[1], q[2]));
  }
  return joint.X_PJ;
}

/// Column k of the joint's motion subspace S, in the child frame.
inline Vector6d MotionSubspaceColumn(const Joint& joint, int k) {
  Vector6d s = Vector6d::Zero();
  switch (joint.type) {
    case JointType::kRevolute:
      s.head<3>() = joint.axis;
      break;
    case JointType::kPrismatic:
      s.tail<3>() = joint.axis;
      break;
    case JointType::kFloating:
      s[k] = 1.0;
      break;
    case JointType::kFixed:
      break;
  }
  return s;
}

/// S * x for the joint's slice x of a velocity-sized vector (pointer to its first element).
inline Vector6d ApplyMotionSubspace(const Joint& joint, const double* x) {
  Vector6d s = Vector6d::Zero();
  switch (joint.type) {
    case JointType::kRevolute:
      s.head<3>() = joint.axis * x[0];
      break;
    case JointType::kPrismatic:
      s.tail<3>() = joint.axis * x[0];
      break;
    case JointType::kFloating:
      s = Eigen::Map<const Vector6d>(x);
      break;
    case JointType::kFixed:
      break;
  }
  return s;
}

/// Writes S^T f into the joint's slice of a velocity-sized vector.
inline void ApplyMotionSubspaceTranspose(const Joint& joint, const Vector6d& f, double* out) {
  switch (joint.type) {
    case JointType::kRevolute:
      out[0] = joint.axis.dot(f.head<3>());
      break;
    case JointType::kPrismatic:
      out[0] = joint.axis.dot(f.tail<3>());
      break;
    case JointType::kFloating: {
      Eigen::Map<Vector6d> target(out);
      target = f;
      break;
    }
    case JointType::kFixed:
      break;
  }
}

}  // namespace cairn::multibody::internal
