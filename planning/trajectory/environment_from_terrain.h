#pragma once

#include <vector>

#include <cairn/planning/footstep/terrain_map.h>
#include <cairn/planning/trajectory/collision_penalty.h>

namespace cairn::planning {

/// The whole-body problem's environment from a terrain: its box obstacles (EnvironmentFromObstacles, probability
/// 1) followed by one cube per occupied voxel, named "voxel <i>", with the voxel's occupancy probability, so the
/// collision term weighs perceived space by how likely it is occupied (stereo uncertainty in the whole-body
/// problem; thesis 5.3.2). Every environment box is checked at every waypoint and sample: assemble the terrain
/// with an occupied_threshold that keeps the voxel count to what the solve can afford.
std::vector<EnvironmentBox> EnvironmentFromTerrain(const TerrainMap& terrain);

}  // namespace cairn::planning
