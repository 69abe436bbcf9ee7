#include <cairn/planning/run/main_diagram.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>

#include <cairn/common/number_text.h>
#include <cairn/systems/framework/diagram_builder.h>

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
  // lose their ground, and gaps up to 10 cm between level ground are bridged (docs/main_diagram.md).
  setup.terrain.fusion = MaterialFusion::kIndependent;
  setup.terrain.outlier_height = 0.02;
  setup.terrain.max_gap = 0.1;
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

MainDiagram BuildMainDiagram(const WalkSetup& walk_setup, const PerceptionSetup& perception,
                             std::unique_ptr<systems::System> camera) {
  if (camera == nullptr) throw std::invalid_argument("BuildMainDiagram: the camera is null; give a stereo source");
  if (perception.grid == nullptr) {
    throw std::invalid_argument("BuildMainDiagram: PerceptionSetup::grid is null; give the occupancy grid's prototype");
  }
  if (perception.segmenter == nullptr) {
    throw std::invalid_argument("BuildMainDiagram: PerceptionSetup::segmenter is null; give a material segmenter "
                                "(e.g. MakeMaterialSegmenter(\"builtin\"))");
  }
  for (const char* port : {"left", "right", "left_colour", "X_WC"}) {
    if (!camera->HasOutputPort(port)) {
      throw std::invalid_argument("BuildMainDiagram: the camera '" + camera->get_name() + "' has no output '" + port +
                                  "'; the main diagram needs left, right, left_colour and X_WC (SyntheticStereoSource "
                                  "has them)");
    }
  }
  systems::DiagramBuilder builder;
  MainDiagram main;
  systems::System* source = builder.AddSystem(std::move(camera));
  source->set_name("camera");
  auto* stereo = builder.AddNamedSystem<perception::StereoMatcher>("stereo", perception.matcher);
  auto* depth = builder.AddNamedSystem<perception::DisparityToDepth>("depth", perception.calibration, perception.depth);
  auto* occupancy = builder.AddNamedSystem<perception::ConfidenceToOccupancy>(
      "occupancy", *perception.grid, perception.calibration, perception.period, perception.occupancy,
      perception.period);
  perception::FrictionEstimator::Options friction_options;
  friction_options.eta = perception.eta;
  friction_options.num_threads = perception.num_threads;
  friction_options.with_geometry = true;
  friction_options.camera = perception.calibration;
  auto* friction = builder.AddNamedSystem<perception::FrictionEstimator>("friction", perception.registry,
                                                                         perception.segmenter, friction_options);
  TerrainAssemblyOptions terrain_options = perception.terrain;
  terrain_options.eta = perception.eta;
  auto* terrain = builder.AddNamedSystem<TerrainAssembler>("terrain_assembler", perception.registry, terrain_options);

  builder.Connect(source->GetOutputPort("left"), stereo->get_left_input_port());
  builder.Connect(source->GetOutputPort("right"), stereo->get_right_input_port());
  builder.Connect(stereo->get_confidence_output_port(), occupancy->get_confidence_input_port());
  builder.Connect(source->GetOutputPort("X_WC"), occupancy->get_pose_input_port());
  builder.Connect(stereo->get_wta_output_port(), depth->get_wta_input_port());
  builder.Connect(source->GetOutputPort("left_colour"), friction->GetInputPort("image"));
  builder.Connect(depth->get_depth_output_port(), friction->GetInputPort("depth"));
  builder.Connect(source->GetOutputPort("X_WC"), friction->GetInputPort("X_WC"));
  builder.Connect(occupancy->get_grid_output_port(), terrain->get_grid_input_port());
  builder.Connect(friction->GetOutputPort("friction_points"), terrain->get_friction_points_input_port());

  main.walk = AddWalkBlocks(walk_setup, &terrain->get_terrain_output_port(), &builder);
  main.walk.diagram = builder.Build();
  main.walk.diagram->set_name("main");
  main.camera = source;
  main.stereo = stereo;
  main.depth = depth;
  main.occupancy = occupancy;
  main.friction = friction;
  main.terrain = terrain;
  return main;
}

MainStart InitializeMainDiagram(const MainDiagram& main, systems::Simulator* simulator) {
  if (simulator == nullptr || &simulator->get_system() != main.walk.diagram.get()) {
    throw std::invalid_argument("InitializeMainDiagram: the simulator does not simulate this main diagram");
  }
  MainStart start;
  systems::Context& root = simulator->get_mutable_context();
  const auto t0 = std::chrono::steady_clock::now();
  simulator->Initialize();
  const auto t1 = std::chrono::steady_clock::now();
  const systems::Diagram& diagram = *main.walk.diagram;
  main.occupancy->ExecuteForcedEvents(&diagram.GetMutableSubsystemContext(*main.occupancy, &root));
  main.terrain->get_terrain_output_port().Eval<TerrainMap>(diagram.GetSubsystemContext(*main.terrain, root));
  start.perception_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t1).count();
  start.walk = SettleWalk(main.walk, &root, /*replan_footsteps=*/true);
  // Simulator::Initialize() ran the planners' initialization events on the empty grid; that time counts too.
  start.walk.seconds.footsteps += std::chrono::duration<double>(t1 - t0).count();
  return start;
}

MainRecord RunMainDiagram(const MainDiagram& main, WalkRunOptions options) {
  MainRecord record;
  const systems::Context* root = nullptr;
  options.initialize = [&](systems::Simulator* simulator) {
    const MainStart start = InitializeMainDiagram(main, simulator);
    record.perception_seconds = start.perception_seconds;
    root = &simulator->get_context();
    record.terrain = std::make_shared<const TerrainMap>(main.terrain->get_terrain_output_port().Eval<TerrainMap>(
        main.walk.diagram->GetSubsystemContext(*main.terrain, *root)));
    return start.walk;
  };
  record.walk = RunWalk(main.walk, options);
  return record;
}

}  // namespace cairn::planning
