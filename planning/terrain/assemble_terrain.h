#pragma once

#include <cairn/perception/friction/friction_point_cloud.h>
#include <cairn/perception/friction/friction_quantile.h>
#include <cairn/perception/friction/material_registry.h>
#include <cairn/perception/occupancy/occupancy_grid.h>
#include <cairn/planning/footstep/terrain_map.h>

namespace cairn::planning {

/// How AssembleTerrain reads the occupancy grid and the friction points.
struct TerrainAssemblyOptions {
  /// Occupancy cells with a probability above this are surfaces or obstacles (0.5: any evidence of occupation).
  double occupied_threshold{0.5};
  /// Highest world z (m) a foot can stand at: occupied cells whose centre lies above it are never ground, only
  /// obstacles for the body (the body's reach: a table top is not a foothold).
  double max_ground_height{0.3};
  /// Friction is at least the cell's quantile with probability eta (the chance constraint of thesis eq. 5.3;
  /// FrictionEstimator's eta).
  double eta{0.95};
  perception::QuantileMethod quantile_method{perception::QuantileMethod::kExact};
  /// Friction points a ground cell needs before its friction is known.
  int min_points{1};
  /// Friction of a ground cell with fewer than min_points points: 0 (the default) makes it not walkable, so the
  /// planner never steps where the camera has not seen the material; a positive value trusts it that much.
  double unknown_friction{0.0};
};

/// Throws std::invalid_argument naming the first option out of range and its range.
void ValidateTerrainAssemblyOptions(const TerrainAssemblyOptions& options);

/// The planners' terrain from perception (thesis 5.2: geometry and friction fused into one map), keeping the
/// distributions until the end.
///
/// Grid: one terrain cell per occupancy column, same resolution and horizontal extent.
///
/// Ground: in each column, the highest occupied cell (centre at most max_ground_height) confirmed by the friction
/// points -- at least min_points of them within one layer of it (a surface on a layer boundary spreads its points
/// over two layers) -- else, without points, the highest occupied cell; a column with no occupied cell has no
/// ground. The surface's points are those within one layer of the ground cell; its height is their median z (the
/// surface itself, not the cell's quantised face), or the cell's top face when there are none.
///
/// Friction: the material mixture weights of the ground surface's points are averaged (the mixture of the
/// points' mixtures), and the cell's friction is that mixture's Q_{1-eta} under `registry` (FrictionQuantile):
/// the quantile of the fused distribution, not a mean of the points' quantiles, which would be optimistic for a
/// cell where two materials meet. A cell with fewer than min_points points gets unknown_friction.
///
/// Obstacles: every occupied cell above its column's ground cell (all of them in a column without ground; an
/// unconfirmed cell above the surface too, e.g. a stereo mismatch) becomes an occupied voxel of the map with its
/// occupancy probability (TerrainMap::SetOccupiedVoxels), for the planners' probabilistic body check.
///
/// Throws std::invalid_argument for bad options, friction points whose weights do not have one column per
/// registry label or one row per point, or more occupied voxels than TerrainMap::kMaxVoxels.
TerrainMap AssembleTerrain(const perception::OccupancyGrid& grid, const perception::FrictionPointCloud& points,
                           const perception::MaterialRegistry& registry,
                           const TerrainAssemblyOptions& options = TerrainAssemblyOptions());

}  // namespace cairn::planning
