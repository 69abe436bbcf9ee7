#pragma once

#include <string>
#include <vector>

#include <Eigen/Core>

#include <cairn/perception/terrain/grid_map.h>
#include <cairn/planning/scenarios/probing_diagram.h>

namespace cairn::cli {

/// A top-down PNG of one layer of a probing diagram run's global map, encoded in memory (to be written atomically):
/// `layer` coloured from `lo` to `hi` (viridis; unknown cells grey), or, for layer "semantics", plants green and
/// water blue by their fused probabilities; the robot's trajectory white, the last plan magenta, probes as rings
/// (red: collapsible, C >= 0.5; green: not) with the start and goal marked; below the map a colour bar with its
/// range and unit, and a 1 m scale bar. Throws std::runtime_error if encoding fails.
std::string TraverseLayerPng(const perception::GridMap& map, const std::string& layer, double lo, double hi,
                             const std::string& unit, const planning::TraverseScenario& scenario,
                             const planning::ProbingRun& result);

}  // namespace cairn::cli
