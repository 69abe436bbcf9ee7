#include <cairn/planning/run/perception_diagram.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>

#include <cairn/common/number_text.h>

namespace cairn::planning {

PerceptionSetup PerceptionSetupFromScenario(const FootstepScenario& scenario,
                                            const perception::StereoCalibration& calibration,
                                            std::shared_ptr<const perception::MaterialSegmenter> segmenter,
                                            double max_depth) {
  if (segmenter == nullptr) {
    throw std::invalid_argument("PerceptionSetupFromScenario: the segmenter is null; give a material segmenter");
  }
  calibration.Validate();
  if (!(max_depth > 0.5 && max_depth <= 100.0)) {
    throw std::invalid_argument("PerceptionSetupFromScenario: max_depth must be in (0.5, 100] m; got " +
                                cairn::FormatShort(max_depth));
  }
  PerceptionSetup setup;
  setup.calibration = calibration;
  setup.segmenter = std::move(segmenter);
  setup.registry = scenario.registry();
  setup.eta = scenario.eta();
  // A cell's points as independent looks at its one material: a calibrated segmenter leaves a few per cent of each
  // pixel's mass on labels it doubts, and averaged that made half of the mock-up's tiles not walkable at
  // eta = 0.95. A single frame's mismatches on a surface without texture stand centimetres off it: those cells
  // lose their ground, the rest take their neighbourhood's median height (the noise left is otherwise near the
  // planner's 2 cm flatness tolerance), and gaps up to 20 cm between level ground are bridged: the mock-up's tile
  // faces have no texture across most of their 30 cm, and one frame leaves holes that wide in them
  // (docs/main_diagram.md).
  setup.terrain.fusion = MaterialFusion::kIndependent;
  setup.terrain.outlier_height = 0.02;
  setup.terrain.outlier_radius = 0.075;
  setup.terrain.median_heights = true;
  setup.terrain.max_gap = 0.2;
  const double resolution = std::max(scenario.resolution(), 0.025);
  double lowest = 0.0, highest = 0.0;
  if (!scenario.regions().empty()) {
    lowest = highest = scenario.regions().front().height;
    for (const auto& region : scenario.regions()) {
      for (const auto& p : region.polygon) {
        lowest = std::min(lowest, region.HeightAt(p));
        highest = std::max(highest, region.HeightAt(p));
      }
    }
  }
  const Eigen::Vector3d min_corner(scenario.min_corner().x(), scenario.min_corner().y(), lowest - 0.1);
  const Eigen::Vector3d extent(scenario.max_corner().x() - scenario.min_corner().x(),
                               scenario.max_corner().y() - scenario.min_corner().y(), highest + 1.0 - min_corner.z());
  const Eigen::Vector3i dims = (extent / resolution).array().ceil().cast<int>().max(1);
  const double cells = static_cast<double>(dims.x()) * dims.y() * dims.z();
  constexpr double kMaxGridCells = 2e7;
  if (cells > kMaxGridCells) {
    throw std::invalid_argument("PerceptionSetupFromScenario: the occupancy grid over '" + scenario.path() + "' would have " +
                                cairn::FormatShort(cells) + " cells (at most 2e7); map a smaller area or a coarser resolution");
  }
  setup.grid = std::make_shared<const perception::OccupancyGrid>(min_corner, resolution, dims);
  const double fb = calibration.depth_times_disparity();
  setup.matcher.cost_volume.min_disparity = std::max(0, static_cast<int>(std::floor(fb / max_depth)));
  setup.matcher.cost_volume.max_disparity =
      std::max(setup.matcher.cost_volume.min_disparity + 1, static_cast<int>(std::ceil(fb / 0.5)));
  return setup;
}

PerceptionBlocks AddPerceptionBlocks(const PerceptionSetup& perception, const CameraPorts& camera,
                                     systems::DiagramBuilder* builder) {
  if (builder == nullptr) throw std::invalid_argument("AddPerceptionBlocks: the builder is null");
  if (perception.grid == nullptr) {
    throw std::invalid_argument("AddPerceptionBlocks: PerceptionSetup::grid is null; give the occupancy grid's prototype");
  }
  if (perception.segmenter == nullptr) {
    throw std::invalid_argument("AddPerceptionBlocks: PerceptionSetup::segmenter is null; give a material segmenter "
                                "(e.g. MakeMaterialSegmenter(\"builtin\"))");
  }
  for (const auto& [port, name] : {std::pair{camera.left, "left"}, {camera.right, "right"},
                                   {camera.left_colour, "left_colour"}, {camera.X_WC, "X_WC"}}) {
    if (port == nullptr) {
      throw std::invalid_argument(std::string("AddPerceptionBlocks: the camera's `") + name +
                                  "` port is null; give all four CameraPorts");
    }
  }
  PerceptionBlocks blocks;
  auto* stereo = builder->AddNamedSystem<perception::StereoMatcher>("stereo", perception.matcher);
  auto* depth = builder->AddNamedSystem<perception::DisparityToDepth>("depth", perception.calibration, perception.depth);
  auto* occupancy = builder->AddNamedSystem<perception::ConfidenceToOccupancy>(
      "occupancy", *perception.grid, perception.calibration, perception.period, perception.occupancy,
      perception.period);
  perception::FrictionEstimator::Options friction_options;
  friction_options.eta = perception.eta;
  friction_options.num_threads = perception.num_threads;
  friction_options.with_geometry = true;
  friction_options.camera = perception.calibration;
  auto* friction = builder->AddNamedSystem<perception::FrictionEstimator>("friction", perception.registry,
                                                                          perception.segmenter, friction_options);
  TerrainAssemblyOptions terrain_options = perception.terrain;
  terrain_options.eta = perception.eta;
  auto* terrain = builder->AddNamedSystem<TerrainAssembler>("terrain_assembler", perception.registry, terrain_options);

  builder->Connect(*camera.left, stereo->get_left_input_port());
  builder->Connect(*camera.right, stereo->get_right_input_port());
  builder->Connect(stereo->get_confidence_output_port(), occupancy->get_confidence_input_port());
  builder->Connect(*camera.X_WC, occupancy->get_pose_input_port());
  builder->Connect(stereo->get_wta_output_port(), depth->get_wta_input_port());
  builder->Connect(*camera.left_colour, friction->GetInputPort("image"));
  builder->Connect(depth->get_depth_output_port(), friction->GetInputPort("depth"));
  builder->Connect(*camera.X_WC, friction->GetInputPort("X_WC"));
  builder->Connect(occupancy->get_grid_output_port(), terrain->get_grid_input_port());
  builder->Connect(friction->GetOutputPort("friction_points"), terrain->get_friction_points_input_port());
  blocks.stereo = stereo;
  blocks.depth = depth;
  blocks.occupancy = occupancy;
  blocks.friction = friction;
  blocks.terrain = terrain;
  return blocks;
}

}  // namespace cairn::planning
