#pragma once

#include <string>

#include <cairn/planning/footstep/biped_geometry.h>
#include <cairn/planning/footstep/foot_pose.h>
#include <cairn/planning/footstep/footstep_plan.h>
#include <cairn/planning/footstep/terrain_map.h>

namespace cairn::cli {

/// Writes a top-down PNG of a plan (atomically): terrain coloured by friction (red at 0 through yellow to green
/// at 1 and above, shaded by height; black without ground), obstacles dark grey, the start stance white, the goal
/// yellow, and each planned sole outlined (left blue, right red). `pixels_per_metre` sets the scale.
void WritePlanImage(const std::string& path, const planning::TerrainMap& terrain, const planning::FootstepPlan& plan,
                    const planning::StanceGoal& goal, const planning::BipedGeometry& geometry,
                    double pixels_per_metre = 100.0);

}  // namespace cairn::cli
