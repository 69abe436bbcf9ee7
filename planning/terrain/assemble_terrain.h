#pragma once

#include <cairn/perception/friction/friction_point_cloud.h>
#include <cairn/perception/friction/friction_quantile.h>
#include <cairn/perception/friction/material_registry.h>
#include <cairn/perception/occupancy/occupancy_grid.h>
#include <cairn/planning/footstep/terrain_map.h>

namespace cairn::planning {

/// How a ground cell's friction points' material mixtures become the cell's one mixture.
enum class MaterialFusion {
  /// The mean of the points' mixtures (a linear opinion pool): what the points say on average. Conservative: a
  /// segmenter that leaves 5 % of every pixel's mass on non-walkable labels leaves it on the cell too, and at
  /// eta = 0.95 that makes its quantile 0.
  kAverage,
  /// Each point an independent observation of the cell's one material (the recursive Bayesian update of semantic
  /// mapping, e.g. SemanticFusion): the cell's mixture is the normalised product of the points' mixtures, under a
  /// uniform prior over the labels. Evidence that agrees sharpens the mixture; a cell where two materials meet
  /// keeps both. Overconfident where the points are not independent (neighbouring pixels share a segmenter's
  /// window, so a label it gets wrong over a whole patch is wrong with certainty).
  kIndependent,
};

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
  /// How a cell's points' material mixtures are fused before the quantile is taken.
  MaterialFusion fusion{MaterialFusion::kAverage};
  /// A ground cell whose height differs from the median height of the ground within `outlier_radius` (m, a square
  /// window) by more than `outlier_height` (m) loses its ground: a single frame's stereo mismatches on a surface
  /// without texture leave cells centimetres above or below it (measured on the mock-up's tiles: from -5 to +6 cm).
  /// A cell that stood above the median keeps its occupied cells as obstacle voxels (a post narrower than the
  /// window is an obstacle, not a floor) and is never bridged; one below it leaves a gap that may be (max_gap). A
  /// window of fewer than 3 ground cells judges nothing. 0 (the default) keeps every cell.
  double outlier_height{0.0};
  double outlier_radius{0.05};
  /// Every ground cell (that outlier_height keeps) takes the median height of the ground within outlier_radius: a
  /// median filter, which flattens a single frame's centimetre noise on a level floor and keeps a step's edge
  /// where the window holds more of one side than of the other.
  bool median_heights{false};
  /// Widest gap in the ground (m) to bridge, as a surface mesh over the points would (thesis 5.2.3 meshes its
  /// point cloud): a column without ground whose nearest ground cells on two opposite sides (along x or along y),
  /// at most this far apart, stand within `max_gap_step` of each other gets ground interpolated between them, with
  /// the lower of their two frictions. Stereo leaves such gaps where a surface has no texture (the mock-up's tile
  /// faces); a real hole that narrow would be bridged too, so 0 (the default) bridges nothing.
  double max_gap{0.0};
  /// Largest height difference (m) between the two sides of a gap that may be bridged.
  double max_gap_step{0.01};
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
/// Friction: the material mixture weights of the ground surface's points are fused (`fusion`: averaged, or
/// multiplied as independent observations), and the cell's friction is that mixture's Q_{1-eta} under `registry`
/// (FrictionQuantile): the quantile of the fused distribution, not a mean of the points' quantiles, which would be
/// optimistic for a cell where two materials meet. A cell with fewer than min_points points gets unknown_friction.
///
/// Outliers and gaps: see outlier_height and max_gap; a bridged cell's normal comes from the height field like any other's.
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
