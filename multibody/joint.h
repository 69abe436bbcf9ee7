#pragma once

#include <limits>
#include <string>

#include <Eigen/Core>

#include <cairn/multibody/pose.h>

namespace cairn::multibody {

/// Joint kinds. The floating joint's configuration is [x, y, z, qw, qx, qy, qz] (position of the child in the
/// parent, then a unit quaternion R_PC) and its velocity is the child's twist in the child frame [ω_C; v_C].
enum class JointType {
  kFixed,      ///< nq = nv = 0.
  kRevolute,   ///< nq = nv = 1, rotation about `axis` (a continuous URDF joint is a revolute joint without limits).
  kPrismatic,  ///< nq = nv = 1, translation along `axis`.
  kFloating,   ///< nq = 7, nv = 6.
};

/// Returns "fixed", "revolute", "prismatic" or "floating".
const char* JointTypeName(JointType type);

/// The joint connecting a body to its parent. The child frame C is X_PJ * (joint motion): the joint frame J
/// sits at the child's origin when the joint is at zero.
struct Joint {
  /// Joint name (unique within a model).
  std::string name;
  /// Kind of joint.
  JointType type = JointType::kFixed;
  /// Index of the parent body.
  int parent = -1;
  /// Pose of the joint frame in the parent body's frame.
  Pose X_PJ;
  /// Unit axis in the joint (= child) frame, for revolute and prismatic joints.
  Eigen::Vector3d axis = Eigen::Vector3d::UnitZ();
  /// First index of this joint's coordinates in q.
  int idx_q = 0;
  /// First index of this joint's velocities in v.
  int idx_v = 0;
  /// Number of configuration coordinates.
  int nq = 0;
  /// Number of velocity coordinates.
  int nv = 0;
  /// Lower position limit (revolute/prismatic); -infinity when unlimited.
  double lower_limit = -std::numeric_limits<double>::infinity();
  /// Upper position limit (revolute/prismatic); +infinity when unlimited.
  double upper_limit = std::numeric_limits<double>::infinity();
  /// Velocity limit (same for every velocity of the joint); +infinity when unlimited.
  double velocity_limit = std::numeric_limits<double>::infinity();
  /// Effort limit (N m or N); +infinity when unlimited.
  double effort_limit = std::numeric_limits<double>::infinity();
  /// Derived by ModelBuilder (a caller's value is overwritten): 0, 1 or 2 if `axis` is +-x, +-y or +-z, so the
  /// algorithms can build the joint rotation without Rodrigues' formula; -1 for a general axis.
  int axis_index = -1;
  /// Derived by ModelBuilder: the sign of `axis` along axis_index (+1 or -1).
  double axis_sign = 1.0;
  /// Derived by ModelBuilder: true if X_PJ has no rotation, which saves a matrix product per call.
  bool origin_rotation_is_identity = false;
  /// True if the URDF joint was `continuous` (kept for reporting; it behaves as an unlimited revolute joint).
  bool continuous = false;
};

}  // namespace cairn::multibody
