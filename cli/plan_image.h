#pragma once

#include <string>
#include <utility>

#include <cairn/planning/footstep/biped_geometry.h>
#include <cairn/planning/footstep/foot_pose.h>
#include <cairn/planning/footstep/footstep_plan.h>
#include <cairn/planning/footstep/terrain_map.h>

namespace cairn::cli {

/// The size in pixels of the map panel of `terrain`'s plan image (width, height): `pixels_per_metre`, raised so
/// that the longer side has at least 600 pixels. Throws std::invalid_argument if the whole picture (with its axes
/// and legend) would exceed 64 million pixels, so that a command can check before planning.
std::pair<int, int> PlanImageSize(const planning::TerrainMap& terrain, double pixels_per_metre = 100.0);

/// A top-down PNG of a plan, encoded in memory (to be written atomically): `title` above a map of the terrain
/// coloured by friction (red at 0 through yellow to green at 1 and above, darker where lower; black without
/// ground), obstacles dark grey, the start stance white, the goal yellow, and each planned sole outlined (left
/// blue, right red); metric axes, and under them the friction colour bar and the key. Throws as PlanImageSize, or
/// std::runtime_error if encoding fails.
std::string PlanImagePng(const planning::TerrainMap& terrain, const planning::FootstepPlan& plan,
                         const planning::StanceGoal& goal, const planning::BipedGeometry& geometry,
                         const std::string& title = "footstep plan, from above", double pixels_per_metre = 100.0);

}  // namespace cairn::cli
