#pragma once

#include <memory>
#include <string>

#include <cairn/planning/run/perception_diagram.h>
#include <cairn/planning/walk/walk_diagram.h>
#include <cairn/planning/walk/walk_run.h>
#include <cairn/systems/analysis/simulator.h>
#include <cairn/systems/framework/diagram.h>
#include <cairn/systems/framework/leaf_system.h>

namespace cairn::planning {

/// The main diagram (DESIGN.md 3.6, thesis Fig. 5.1): perception in front of the walk.
///
///     camera ─► StereoMatcher ─► ConfidenceToOccupancy ───────────────────┐
///       │             └─► DisparityToDepth ─► FrictionEstimator ─► TerrainAssembler ─► (the walk diagram's
///       └────────────────────── colour, X_WC ──────┘                         FootstepPlanner ─► ... ─► HumanoidPlant)
///
/// The camera is any system with outputs `left`, `right` (8-bit grey), `left_colour` (BGR) and `X_WC` (left
/// camera pose), e.g. perception::SyntheticStereoSource. Subsystem names: "camera", "stereo", "depth",
/// "occupancy", "friction", "terrain_assembler", then the walk's (WalkDiagram, without its "terrain" source).
struct MainDiagram {
  /// walk.diagram is the whole main diagram (so InitializeWalk-style helpers take it); walk's pointers are its blocks.
  WalkDiagram walk;
  const systems::System* camera{nullptr};
  const perception::StereoMatcher* stereo{nullptr};
  const perception::DisparityToDepth* depth{nullptr};
  const perception::ConfidenceToOccupancy* occupancy{nullptr};
  const perception::FrictionEstimator* friction{nullptr};
  const TerrainAssembler* terrain{nullptr};
};

/// Builds the main diagram from the walk's setup (its `terrain` is ignored: the planner reads the assembled one)
/// and the perception setup. Throws std::invalid_argument for a null camera, grid or segmenter, a camera without
/// the four outputs, and as the blocks do.
MainDiagram BuildMainDiagram(const WalkSetup& walk, const PerceptionSetup& perception,
                             std::unique_ptr<systems::System> camera);

/// What InitializeMainDiagram left: the walk's start and the perception's wall time.
struct MainStart {
  WalkStart walk;
  double perception_seconds{0.0};  ///< first frame: stereo, occupancy, friction and terrain assembly
};

/// Perceives, then plans, then settles the walk: Simulator::Initialize(), the occupancy's forced update (the
/// first frame; its periodic updates start one period later, so the frame is fused once), the terrain's
/// evaluation, then SettleWalk(replan_footsteps = true): the FootstepPlanner plans on the perceived terrain, the
/// TrajectoryOptimizer and the Stabilizer follow, and the plant is put on the reference's first sample.
MainStart InitializeMainDiagram(const MainDiagram& main, systems::Simulator* simulator);

/// Everything a main-diagram run produced: the walk's record, what the first frame's perception made (the
/// products the plan was made on) and the perception's time. The images are empty and the pointers null if the
/// run stopped before perceiving.
struct MainRecord {
  WalkRecord walk;
  std::shared_ptr<const TerrainMap> terrain;  ///< the assembled terrain the plan was made on
  std::shared_ptr<const perception::OccupancyGrid> grid;  ///< the occupancy grid it was assembled from
  cv::Mat image;                   ///< the camera's left colour image (BGR)
  cv::Mat material_probabilities;  ///< CV_32FC(registry labels), P(x_k = l_i) in registry order
  cv::Mat friction_quantile;       ///< CV_32F, Q_{1-eta} per pixel
  double perception_seconds{0.0};  ///< wall time of the first frame's perception (not part of any result)
};

/// RunWalk() with InitializeMainDiagram() as its initializer (options.initialize is replaced). Throws as RunWalk.
MainRecord RunMainDiagram(const MainDiagram& main, WalkRunOptions options = WalkRunOptions());

}  // namespace cairn::planning
