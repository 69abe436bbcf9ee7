#pragma once

#include <Eigen/Core>

namespace cairn::planning {

/// The shape of a biped as the footstep planner sees it: sole rectangles that need ground under them, and a box
/// around the body above the knees that must stay clear of obstacles (the thesis' shrunk bounding box, 2.5.2).
struct BipedGeometry {
  double foot_length{0.24};  ///< sole, along the foot's x axis, m
  double foot_width{0.14};   ///< m
  /// Half extents of the body box in the stance frame (x forward along the mean foot yaw), m.
  Eigen::Vector3d body_half_extents{0.15, 0.25, 0.35};
  /// Height of the body box's lower face above the higher sole, m.
  double body_bottom{0.45};
};

}  // namespace cairn::planning
