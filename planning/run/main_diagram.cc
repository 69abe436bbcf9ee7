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
  const PerceptionBlocks blocks = AddPerceptionBlocks(
      perception,
      {&source->GetOutputPort("left"), &source->GetOutputPort("right"), &source->GetOutputPort("left_colour"),
       &source->GetOutputPort("X_WC")},
      &builder);

  main.walk = AddWalkBlocks(walk_setup, &blocks.terrain->get_terrain_output_port(), &builder);
  main.walk.diagram = builder.Build();
  main.walk.diagram->set_name("main");
  main.camera = source;
  main.stereo = blocks.stereo;
  main.depth = blocks.depth;
  main.occupancy = blocks.occupancy;
  main.friction = blocks.friction;
  main.terrain = blocks.terrain;
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
    const systems::Diagram& diagram = *main.walk.diagram;
    record.terrain = std::make_shared<const TerrainMap>(
        main.terrain->get_terrain_output_port().Eval<TerrainMap>(diagram.GetSubsystemContext(*main.terrain, *root)));
    record.grid = std::make_shared<const perception::OccupancyGrid>(
        main.occupancy->get_grid_output_port().Eval<perception::OccupancyGrid>(
            diagram.GetSubsystemContext(*main.occupancy, *root)));
    const systems::Context& friction = diagram.GetSubsystemContext(*main.friction, *root);
    record.image = main.camera->GetOutputPort("left_colour")
                       .Eval<cv::Mat>(diagram.GetSubsystemContext(*main.camera, *root))
                       .clone();
    record.material_probabilities =
        main.friction->GetOutputPort("material_probabilities").Eval<cv::Mat>(friction).clone();
    record.friction_quantile = main.friction->GetOutputPort("friction_quantile").Eval<cv::Mat>(friction).clone();
    return start.walk;
  };
  record.walk = RunWalk(main.walk, options);
  return record;
}

}  // namespace cairn::planning
