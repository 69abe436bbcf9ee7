#pragma once

#include <string>

namespace cairn::planning {

/// Which foot.
enum class FootSide { kLeft, kRight };

/// "left" or "right".
inline const char* FootSideName(FootSide side) { return side == FootSide::kLeft ? "left" : "right"; }
inline FootSide OtherSide(FootSide side) { return side == FootSide::kLeft ? FootSide::kRight : FootSide::kLeft; }

/// A foothold: the pose of a sole's centre in the world frame, as the thesis' f_j = (x, y, z, θ) (2.4.1).
struct FootPose {
  double x{0.0};
  double y{0.0};
  double z{0.0};
  double theta{0.0};  ///< yaw, rad, counter-clockwise from the world x axis
};

/// Two feet on the ground: the thesis' stance s_j = (f_j, f_{j+1}).
struct Stance {
  FootPose left;
  FootPose right;
};

/// Smallest lateral distance between the sole centres of a stance that can stand, m.
inline constexpr double kMinStanceWidth = 1e-3;

/// Why `stance` cannot be a biped's stance, or "" when it can: every coordinate must be finite and the left foot
/// must stand at least kMinStanceWidth to the left of the right one across the stance's mean heading (feet at one
/// point, crossed or one behind the other cannot stand).
std::string StanceGeometryProblem(const Stance& stance);

/// Where a plan must end: a stance, reached when each foot lies within `position_tolerance` (horizontal distance)
/// and `yaw_tolerance` of its goal foothold.
struct StanceGoal {
  Stance stance;
  double position_tolerance{0.1};  ///< m
  double yaw_tolerance{0.27};      ///< rad (about 15°, one of the thesis' 24 footstep directions)
};

}  // namespace cairn::planning
