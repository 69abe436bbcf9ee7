#include <cairn/planning/footstep/foot_pose.h>

#include <cmath>

#include <cairn/common/number_text.h>

namespace cairn::planning {

std::string StanceGeometryProblem(const Stance& stance) {
  for (const auto* foot : {&stance.left, &stance.right}) {
    if (!std::isfinite(foot->x) || !std::isfinite(foot->y) || !std::isfinite(foot->z) || !std::isfinite(foot->theta)) {
      return std::string("the ") + (foot == &stance.left ? "left" : "right") + " foot's pose is not finite";
    }
  }
  // Across the mean heading; feet turned exactly opposite have none, and the left foot's heading is used.
  const double s = std::sin(stance.left.theta) + std::sin(stance.right.theta);
  const double c = std::cos(stance.left.theta) + std::cos(stance.right.theta);
  const double heading = std::hypot(s, c) > 1e-9 ? std::atan2(s, c) : stance.left.theta;
  const double dx = stance.left.x - stance.right.x;
  const double dy = stance.left.y - stance.right.y;
  const double lateral = -std::sin(heading) * dx + std::cos(heading) * dy;
  if (std::hypot(dx, dy) < kMinStanceWidth) {
    return "both feet stand at one point ((" + FormatShort(stance.left.x) + ", " + FormatShort(stance.left.y) +
           ")); put the left foot to the left of the right one";
  }
  if (lateral < kMinStanceWidth) {
    return "the left foot at (" + FormatShort(stance.left.x) + ", " + FormatShort(stance.left.y) +
           ") is not to the left of the right foot at (" + FormatShort(stance.right.x) + ", " +
           FormatShort(stance.right.y) + ") across the stance's heading (" +
           FormatShort(heading * 180.0 / M_PI) + " deg): the feet are crossed or in line; swap them";
  }
  return "";
}

}  // namespace cairn::planning
