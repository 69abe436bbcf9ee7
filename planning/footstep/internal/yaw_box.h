#pragma once

#include <cmath>

#include <Eigen/Core>

namespace cairn::planning::internal {

/// Separating-axis test of two boxes that are each rotated only about the vertical axis: overlap in z, and in
/// the horizontal plane along each box's two edge normals. Touching boxes overlap.
inline bool YawBoxesOverlap(const Eigen::Vector3d& ca, const Eigen::Vector3d& ha, double yaw_a,
                            const Eigen::Vector3d& cb, const Eigen::Vector3d& hb, double yaw_b) {
  if (std::abs(ca.z() - cb.z()) > ha.z() + hb.z()) return false;
  const Eigen::Vector2d d = (cb - ca).head<2>();
  const Eigen::Vector2d axes_a[2] = {{std::cos(yaw_a), std::sin(yaw_a)}, {-std::sin(yaw_a), std::cos(yaw_a)}};
  const Eigen::Vector2d axes_b[2] = {{std::cos(yaw_b), std::sin(yaw_b)}, {-std::sin(yaw_b), std::cos(yaw_b)}};
  for (const Eigen::Vector2d* axes : {axes_a, axes_b}) {
    for (int k = 0; k < 2; ++k) {
      const Eigen::Vector2d& n = axes[k];
      const double ra = ha.x() * std::abs(n.dot(axes_a[0])) + ha.y() * std::abs(n.dot(axes_a[1]));
      const double rb = hb.x() * std::abs(n.dot(axes_b[0])) + hb.y() * std::abs(n.dot(axes_b[1]));
      if (std::abs(n.dot(d)) > ra + rb) return false;
    }
  }
  return true;
}

}  // namespace cairn::planning::internal
