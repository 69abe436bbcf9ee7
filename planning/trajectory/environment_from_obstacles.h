#pragma once

#include <vector>

#include <cairn/planning/footstep/terrain_map.h>
#include <cairn/planning/trajectory/collision_penalty.h>

namespace cairn::planning {

/// The whole-body problem's environment from a terrain's box obstacles (TerrainMap::obstacles(), as scenario
/// files give them): one EnvironmentBox per obstacle, same name, centre, full sizes and yaw. The ground itself is
/// TrajectoryOptimizerOptions::ground_height.
std::vector<EnvironmentBox> EnvironmentFromObstacles(const std::vector<TerrainMap::Obstacle>& obstacles);

}  // namespace cairn::planning
