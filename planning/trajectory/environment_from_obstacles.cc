#include <cairn/planning/trajectory/environment_from_obstacles.h>

#include <Eigen/Geometry>

namespace cairn::planning {

std::vector<EnvironmentBox> EnvironmentFromObstacles(const std::vector<TerrainMap::Obstacle>& obstacles) {
  std::vector<EnvironmentBox> boxes;
  boxes.reserve(obstacles.size());
  for (const TerrainMap::Obstacle& obstacle : obstacles) {
    boxes.push_back({obstacle.name, 2.0 * obstacle.half_extents,
                     multibody::Pose(Eigen::AngleAxisd(obstacle.yaw, Eigen::Vector3d::UnitZ()).toRotationMatrix(),
                                     obstacle.center)});
  }
  return boxes;
}

}  // namespace cairn::planning
