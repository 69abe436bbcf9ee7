#include <cairn/planning/trajectory/environment_from_terrain.h>

#include <cairn/common/number_text.h>
#include <cairn/planning/trajectory/environment_from_obstacles.h>

namespace cairn::planning {

std::vector<EnvironmentBox> EnvironmentFromTerrain(const TerrainMap& terrain) {
  std::vector<EnvironmentBox> boxes = EnvironmentFromObstacles(terrain.obstacles());
  boxes.reserve(boxes.size() + terrain.occupied_voxels().size());
  const Eigen::Vector3d size = Eigen::Vector3d::Constant(terrain.voxel_size());
  for (std::size_t i = 0; i < terrain.occupied_voxels().size(); ++i) {
    const TerrainMap::OccupiedVoxel& voxel = terrain.occupied_voxels()[i];
    boxes.push_back({"voxel " + FormatShort(i), size, multibody::Pose(Eigen::Matrix3d::Identity(), voxel.center),
                     voxel.probability});
  }
  return boxes;
}

}  // namespace cairn::planning
