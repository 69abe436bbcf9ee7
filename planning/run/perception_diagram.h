#pragma once

#include <memory>

#include <cairn/perception/friction/friction_estimator.h>
#include <cairn/perception/friction/material_registry.h>
#include <cairn/perception/friction/material_segmenter.h>
#include <cairn/perception/occupancy/confidence_to_occupancy.h>
#include <cairn/perception/occupancy/cost_curve_sensor_model.h>
#include <cairn/perception/occupancy/occupancy_grid.h>
#include <cairn/perception/stereo/disparity_to_depth.h>
#include <cairn/perception/stereo/stereo_calibration.h>
#include <cairn/perception/stereo/stereo_matcher.h>
#include <cairn/planning/scenarios/footstep_scenario.h>
#include <cairn/planning/terrain/assemble_terrain.h>
#include <cairn/planning/terrain/terrain_assembler.h>
#include <cairn/systems/framework/diagram_builder.h>
#include <cairn/systems/framework/output_port.h>

namespace cairn::planning {

/// How the main diagram perceives: the camera's intrinsics, stereo matching, the occupancy grid it fuses into,
/// friction from vision and the terrain assembled from both.
struct PerceptionSetup {
  perception::StereoCalibration calibration;        ///< the camera's (left) intrinsics and baseline
  perception::StereoMatcher::Options matcher;
  perception::DisparityToDepthOptions depth;        ///< which disparities become friction points
  /// The grid's extent and resolution (its prototype: usually all unknown); its horizontal cells become the
  /// planner's terrain cells, so 2.5 cm suits the footstep lattice.
  std::shared_ptr<const perception::OccupancyGrid> grid;
  perception::CostCurveSensorModel::Options occupancy;
  /// Seconds between the frames fused after the first; the first is fused before planning (InitializeMainDiagram).
  double period{1.0};
  perception::MaterialRegistry registry{perception::MaterialRegistry::ThesisTable33()};
  std::shared_ptr<const perception::MaterialSegmenter> segmenter;  ///< required
  double eta{0.95};                                 ///< the friction chance constraint's level (FrictionEstimator's and the terrain's)
  int num_threads{0};                               ///< the friction estimator's (0: one per core)
  TerrainAssemblyOptions terrain;                   ///< its eta is set from `eta`
};

/// Perception for a footstep scenario seen by a camera of `calibration`: an unknown occupancy grid over the
/// scenario's mapped area at its raster resolution (at least 2.5 cm), from 10 cm below its lowest region to 1 m
/// above its highest (obstacles the body could meet); the scenario's material registry and eta; the matcher's
/// disparity range covering depths from 0.5 m to `max_depth`; and a terrain assembly for a single frame of a
/// calibrated segmenter (docs/main_diagram.md): MaterialFusion::kIndependent, outliers beyond 2 cm of the median
/// within 7.5 cm dropped and the rest set to it (median_heights), gaps up to 20 cm bridged. Throws std::invalid_argument for a null segmenter or
/// a grid above OccupancyGrid's cell limit.
PerceptionSetup PerceptionSetupFromScenario(const FootstepScenario& scenario,
                                            const perception::StereoCalibration& calibration,
                                            std::shared_ptr<const perception::MaterialSegmenter> segmenter,
                                            double max_depth = 4.0);

/// The camera outputs the perception blocks read: `left`, `right` (8-bit grey), `left_colour` (BGR) and `X_WC`
/// (the left camera's pose in the world), e.g. perception::SyntheticStereoSource's.
struct CameraPorts {
  const systems::OutputPort* left{nullptr};
  const systems::OutputPort* right{nullptr};
  const systems::OutputPort* left_colour{nullptr};
  const systems::OutputPort* X_WC{nullptr};
};

/// The perception blocks AddPerceptionBlocks added, owned by the builder (then by its diagram).
struct PerceptionBlocks {
  const perception::StereoMatcher* stereo{nullptr};
  const perception::DisparityToDepth* depth{nullptr};
  const perception::ConfidenceToOccupancy* occupancy{nullptr};
  const perception::FrictionEstimator* friction{nullptr};
  const TerrainAssembler* terrain{nullptr};
};

/// Adds the perception half of the main diagram to `builder`, wired to `camera`:
///
///     left, right ─► StereoMatcher ─► ConfidenceToOccupancy (with X_WC) ─────────────┐
///                          └─► DisparityToDepth ─► FrictionEstimator (with left_colour, X_WC) ─► TerrainAssembler ─► terrain
///
/// named "stereo", "depth", "occupancy", "friction" and "terrain_assembler". The terrain (TerrainAssembler's
/// `terrain` output) is what a planner reads; nothing is exported. Throws std::invalid_argument for a null grid,
/// segmenter, builder or camera port, and as the blocks do.
PerceptionBlocks AddPerceptionBlocks(const PerceptionSetup& perception, const CameraPorts& camera,
                                     systems::DiagramBuilder* builder);

}  // namespace cairn::planning
