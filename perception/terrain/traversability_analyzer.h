#pragma once

/// @file
/// TraversabilityAnalyzer: Algorithm 1 of seed 001 on a terrain map and the probes so far, as a system.

#include <vector>

#include <Eigen/Core>

#include "cairn/perception/terrain/grid_map.h"
#include "cairn/perception/terrain/hierarchical_traversability.h"
#include "cairn/perception/terrain/probed_region.h"
#include "cairn/systems/framework/leaf_system.h"

namespace cairn::perception {

/// Fuses the probes' collapsibility into the "collapsibility" layer of a copy of the input map (each probed
/// region's points mark their cells, each cell once per probe; probes in their order, by the Kalman rule of eq. 1
/// at the rule's probe_variance, so a cell probed twice holds the mean of the two with half the variance) and computes "traversability" and
/// its measurement variance with HierarchicalTraversability (Algorithm 1). A per-cell rule over the map, cheap
/// enough for an output. The map is the mapper's: fused in place over time when it is fixed in the world;
/// register a robot-centred one (ElevationMapper's follow_sensor) into a fixed global map with MapRegistration
/// and variance_layer "traversability_variance" (seed 001 §4.2).
///
/// | port | type | meaning |
/// |---|---|---|
/// | input `map` | GridMap | elevation, semantic_*, slope, roughness (ElevationMapper's `map`) |
/// | input `probes` | std::vector<ProbedRegion> | every probe so far |
/// | output `map` | GridMap | the input's layers plus collapsibility(_variance) and traversability(_variance) |
/// | output `traversability` | Eigen::MatrixXd | the traversability by map index (i along x, j along y), NaN unknown |
class TraversabilityAnalyzer final : public systems::LeafSystem {
 public:
  /// Throws std::invalid_argument for bad options.
  explicit TraversabilityAnalyzer(const HierarchicalTraversability::Options& options);
  TraversabilityAnalyzer() : TraversabilityAnalyzer(HierarchicalTraversability::Options{}) {}

  const systems::InputPort& get_map_input_port() const { return get_input_port(0); }
  const systems::InputPort& get_probes_input_port() const { return get_input_port(1); }
  const systems::OutputPort& get_map_output_port() const { return get_output_port(0); }
  const systems::OutputPort& get_traversability_output_port() const { return get_output_port(1); }

  /// What the `map` output computes.
  void CalcMap(const GridMap& map, const std::vector<ProbedRegion>& probes, GridMap* out) const;

 private:
  HierarchicalTraversability rule_;
};

}  // namespace cairn::perception
