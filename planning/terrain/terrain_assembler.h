#pragma once

#include <cairn/perception/friction/material_registry.h>
#include <cairn/planning/terrain/assemble_terrain.h>
#include <cairn/systems/framework/leaf_system.h>

namespace cairn::planning {

/// The block between perception and footstep planning (DESIGN.md 3.6): AssembleTerrain over its inputs.
///
/// | port | type | meaning |
/// |---|---|---|
/// | input `grid` | perception::OccupancyGrid | fused occupancy (ConfidenceToOccupancy's output) |
/// | input `friction_points` | perception::FrictionPointCloud | world points with material mixtures (FrictionEstimator) |
/// | output `terrain` | TerrainMap | ground heights, normals, friction Q_{1-eta} per cell, occupied voxels |
///
/// Parameter (per context): the abstract MaterialRegistry (`registry_parameter()`), the friction distributions the
/// fused mixtures are read with; swap in the FrictionEstimator's refined registry when learning from contact.
/// The terrain is cached until an input or the registry changes.
class TerrainAssembler final : public systems::LeafSystem {
 public:
  /// Throws std::invalid_argument for bad options (ValidateTerrainAssemblyOptions).
  TerrainAssembler(perception::MaterialRegistry registry, const TerrainAssemblyOptions& options = TerrainAssemblyOptions());

  int registry_parameter() const { return 0; }
  const TerrainAssemblyOptions& options() const { return options_; }

  const systems::InputPort& get_grid_input_port() const { return GetInputPort("grid"); }
  const systems::InputPort& get_friction_points_input_port() const { return GetInputPort("friction_points"); }
  const systems::OutputPort& get_terrain_output_port() const { return GetOutputPort("terrain"); }

 private:
  TerrainAssemblyOptions options_;
};

}  // namespace cairn::planning
