#pragma once

/// @file
/// Closed-form signed distances between spheres, capsules and boxes, with witness points and normals. They are
/// exact (box-capsule to the precision of a 1-D convex minimisation) and take well under a microsecond, where
/// FCL's signed distance is slow or unreliable (shared/notes/dependencies.md).

#include <limits>

#include <Eigen/Core>

#include <cairn/multibody/pose.h>

namespace cairn::multibody {

/// Result of a distance query between shapes A and B, all in the world frame.
/// `distance` is signed (negative when they overlap); p_A lies on A's surface, p_B on B's, and
/// p_B - p_A = distance * normal, with `normal` the unit direction in which moving B increases the distance.
/// Overlapping boxes are the exception: p_A and p_B are the two boxes' deepest vertices and only
/// normal . (p_B - p_A) = distance holds. In every case, with the points fixed to their bodies,
/// d(distance) = normal . (dp_B - dp_A) for a small motion, which is what collision gradients use.
struct ShapeDistance {
  /// Signed distance.
  double distance = 0.0;
  /// Witness point on A.
  Eigen::Vector3d p_A = Eigen::Vector3d::Zero();
  /// Witness point on B.
  Eigen::Vector3d p_B = Eigen::Vector3d::Zero();
  /// Unit normal from A towards B.
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();
};

/// Sphere (centre, radius) to sphere. Concentric spheres get the normal +z.
ShapeDistance SphereSphereDistance(const Eigen::Vector3d& center_A, double radius_A, const Eigen::Vector3d& center_B,
                                   double radius_B);

/// Sphere to capsule; a capsule is the segment [a, b] swept by a ball of `radius`.
ShapeDistance SphereCapsuleDistance(const Eigen::Vector3d& center_A, double radius_A, const Eigen::Vector3d& a_B,
                                    const Eigen::Vector3d& b_B, double radius_B);

/// Capsule to capsule.
ShapeDistance CapsuleCapsuleDistance(const Eigen::Vector3d& a_A, const Eigen::Vector3d& b_A, double radius_A,
                                     const Eigen::Vector3d& a_B, const Eigen::Vector3d& b_B, double radius_B);

/// Box (pose X_WA, full side lengths `size_A`) to sphere. Inside the box the depth is measured to the nearest face.
ShapeDistance BoxSphereDistance(const Pose& X_WA, const Eigen::Vector3d& size_A, const Eigen::Vector3d& center_B,
                                double radius_B);

/// Box to capsule: minimises the box's signed distance function (convex) along the capsule's axis. When the axis
/// enters the box this is the depth of its deepest point, a lower bound of the penetration depth.
ShapeDistance BoxCapsuleDistance(const Pose& X_WA, const Eigen::Vector3d& size_A, const Eigen::Vector3d& a_B,
                                 const Eigen::Vector3d& b_B, double radius_B);

/// Box to box. Separated boxes get the exact distance (the closest pair is a vertex against a box or an edge
/// against an edge); overlapping boxes get the exact penetration depth along the separating-axis direction of
/// least overlap, with the deepest vertices as witness points (see ShapeDistance). If the boxes are separated by
/// at least `early_out` along some axis, that separation (a lower bound of the distance) is returned at once,
/// without witness points: margin queries use it to skip distant pairs.
ShapeDistance BoxBoxDistance(const Pose& X_WA, const Eigen::Vector3d& size_A, const Pose& X_WB,
                             const Eigen::Vector3d& size_B, double early_out = std::numeric_limits<double>::infinity());

/// Closest points s(s_param) on segment [p1, q1] and t on [p2, q2]; returns the parameters in [0, 1].
void ClosestSegmentParameters(const Eigen::Vector3d& p1, const Eigen::Vector3d& q1, const Eigen::Vector3d& p2,
                              const Eigen::Vector3d& q2, double* s, double* t);

/// Returns the distance with A and B swapped (witness points exchanged, normal negated).
ShapeDistance Swapped(const ShapeDistance& d);

}  // namespace cairn::multibody
