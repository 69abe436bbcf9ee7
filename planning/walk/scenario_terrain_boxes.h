#pragma once

#include <vector>

#include <cairn/multibody/plant/terrain_box.h>
#include <cairn/planning/scenarios/footstep_scenario.h>

namespace cairn::planning {

/// Thickness of every terrain box below its region's surface, m.
inline constexpr double kScenarioTerrainThickness = 1.0;
/// Friction of the obstacles' boxes in the plant (scenario files state none for them).
inline constexpr double kScenarioObstacleFriction = 1.0;

/// A footstep scenario's ground and obstacles as the physics plant's terrain (multibody/plant's TerrainBox): the
/// converter from the planner's world to the plant's that multibody cannot hold (it may not depend on planning).
///
/// Each region must be an axis-aligned rectangle (a `box:` region of the file). As in
/// FootstepScenario::BuildTerrain, later regions paint over earlier ones: the earlier rectangles are cut around the
/// later ones, so the boxes do not overlap and a foot on the ice touches the ice box only. Each piece becomes a
/// box 1 m thick whose top face lies in its region's plane (tilted along the region's normal for a slope; its
/// side lengths are stretched so that its footprint covers the piece along the slope). The true friction of a
/// region is the mean of its friction distribution (exact for a `friction: mu` region; for a material it is the
/// material's mean, while the planner used the (1 - eta) quantile). Obstacles become boxes of friction
/// kScenarioObstacleFriction. Throws std::invalid_argument naming the region that is not an axis-aligned
/// rectangle or slopes along neither x nor y, and when the pieces would exceed BulletPlant::kMaxTerrainBoxes.
std::vector<multibody::TerrainBox> ScenarioTerrainBoxes(const FootstepScenario& scenario);

}  // namespace cairn::planning
