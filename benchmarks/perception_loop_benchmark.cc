// Issue 18's perception loop, one frame at 640 x 480 with 64 disparities: StereoMatcher (cost volume, WTA and the
// whole-range confidence) -> ConfidenceToOccupancy's update -> DisparityToDepth -> FrictionEstimator (segmentation,
// quantiles, world points) -> TerrainAssembler, as AddPerceptionBlocks wires them for the main diagram. The frame is
// the mock-up's (examples/scenarios/mockup/mockup.yaml) seen by the head camera, rendered once: the renderer is
// not part of the loop. Each iteration hands the same images to the sources again, which invalidates every cached
// output downstream, so the loop recomputes everything a new frame would, in the storage of the frame before (a
// frame stream's steady state); the counters split the time by stage (each stage's Eval after the ones it reads). Anchors: thesis 2 Hz, seed 001
// 5 Hz; aim 10 Hz on 2 cores.
//
// `--keep-freed-memory` (before the benchmark's own flags) tells glibc to keep freed memory in the process
// (mallopt: no mmap for large blocks, no trimming): the loop's stages allocate their large temporaries anew each
// frame (the segmenter's feature maps and upsampled probabilities, about 100 MB at 640 x 480), and on this VM the
// page faults of memory returned to the system and taken back cost more than the segmentation itself. The two
// runs together show what that allocation costs.

#include <chrono>
#include <cstring>

#include <malloc.h>
#include <memory>
#include <string>

#include <benchmark/benchmark.h>

#include <Eigen/Geometry>
#include <opencv2/core.hpp>

#include <cairn/perception/friction/make_material_segmenter.h>
#include <cairn/planning/run/perception_diagram.h>
#include <cairn/planning/run/scenario_stereo_scene.h>
#include <cairn/systems/primitives/constant_value_source.h>

namespace {

using namespace cairn;
using Clock = std::chrono::steady_clock;

double Seconds(Clock::time_point a, Clock::time_point b) { return std::chrono::duration<double>(b - a).count(); }

struct Loop {
  std::unique_ptr<systems::Diagram> diagram;
  planning::PerceptionBlocks blocks;
  const systems::System* left{nullptr};
  const systems::System* right{nullptr};
  const systems::System* colour{nullptr};
};

// `segmenter`: 0 the built-in one (the main diagram's default), 1 the ONNX network through OpenCV dnn.
Loop BuildLoop(int width, int height, int segmenter) {
  const std::string source_dir = CAIRN_SOURCE_DIR;
  const planning::FootstepScenario scenario =
      planning::FootstepScenario::Load(source_dir + "/examples/scenarios/mockup/mockup.yaml");
  planning::SyntheticCamera camera;
  camera.width = width;
  camera.height = height;
  // One frame of the head camera, rendered once.
  const auto source = planning::ScenarioCamera(scenario, camera, 1.0);
  const auto source_context = source->CreateDefaultContext();
  const cv::Mat left = source->GetOutputPort("left").Eval<cv::Mat>(*source_context).clone();
  const cv::Mat right = source->GetOutputPort("right").Eval<cv::Mat>(*source_context).clone();
  const cv::Mat colour = source->GetOutputPort("left_colour").Eval<cv::Mat>(*source_context).clone();
  const Eigen::Isometry3d X_WC = source->GetOutputPort("X_WC").Eval<Eigen::Isometry3d>(*source_context);

  planning::PerceptionSetup setup = planning::PerceptionSetupFromScenario(
      scenario, camera.Calibration(),
      perception::MakeMaterialSegmenter(segmenter == 0
                                            ? "builtin:" + source_dir + "/data/models/builtin_material_segmenter.yaml"
                                            : "onnx:" + source_dir + "/data/models/tiny_material_net.yaml"));
  // 64 disparities around the floor the camera sees (1.2-2.5 m ahead of the lens at 640 px: disparities 22-46).
  const double scale = width / 640.0;
  setup.matcher.cost_volume.min_disparity = static_cast<int>(16 * scale);
  setup.matcher.cost_volume.max_disparity = setup.matcher.cost_volume.min_disparity + static_cast<int>(64 * scale) - 1;

  systems::DiagramBuilder builder;
  auto* l = builder.AddNamedSystem<systems::ConstantValueSource<cv::Mat>>("left", left);
  auto* r = builder.AddNamedSystem<systems::ConstantValueSource<cv::Mat>>("right", right);
  auto* c = builder.AddNamedSystem<systems::ConstantValueSource<cv::Mat>>("left_colour", colour);
  auto* x = builder.AddNamedSystem<systems::ConstantValueSource<Eigen::Isometry3d>>("X_WC", X_WC);
  Loop loop;
  loop.blocks = planning::AddPerceptionBlocks(
      setup, {&l->get_output_port(0), &r->get_output_port(0), &c->get_output_port(0), &x->get_output_port(0)},
      &builder);
  loop.diagram = builder.Build();
  loop.left = l;
  loop.right = r;
  loop.colour = c;
  return loop;
}

void BM_PerceptionLoop(benchmark::State& state) {
  const Loop loop = BuildLoop(static_cast<int>(state.range(0)), static_cast<int>(state.range(1)),
                             static_cast<int>(state.range(2)));
  const systems::Diagram& diagram = *loop.diagram;
  const planning::PerceptionBlocks& b = loop.blocks;
  double stereo = 0, occupancy = 0, depth = 0, friction = 0, terrain = 0;
  std::size_t points = 0;
  auto root = diagram.CreateDefaultContext();
  auto new_frame = [&] {
    for (const systems::System* camera : {loop.left, loop.right, loop.colour}) {
      systems::Context& context = diagram.GetMutableSubsystemContext(*camera, root.get());
      cv::Mat& image = context.get_mutable_abstract_parameter<cv::Mat>(0);
      benchmark::DoNotOptimize(image.data);
    }
  };
  // One frame, untimed: the first allocates every output's storage (a frame stream's later frames reuse it).
  auto frame = [&](bool timed) {
    new_frame();
    const auto t1 = Clock::now();
    b.stereo->get_confidence_output_port().Eval<perception::DisparityVolume>(diagram.GetSubsystemContext(*b.stereo, *root));
    b.stereo->get_wta_output_port().Eval<perception::WtaResult>(diagram.GetSubsystemContext(*b.stereo, *root));
    const auto t2 = Clock::now();
    b.occupancy->ExecuteForcedEvents(&diagram.GetMutableSubsystemContext(*b.occupancy, root.get()));
    const auto t3 = Clock::now();
    b.depth->get_depth_output_port().Eval<cv::Mat>(diagram.GetSubsystemContext(*b.depth, *root));
    const auto t4 = Clock::now();
    points = b.friction->GetOutputPort("friction_points")
                 .Eval<perception::FrictionPointCloud>(diagram.GetSubsystemContext(*b.friction, *root))
                 .points_W.size();
    const auto t5 = Clock::now();
    const auto& map = b.terrain->get_terrain_output_port().Eval<planning::TerrainMap>(
        diagram.GetSubsystemContext(*b.terrain, *root));
    benchmark::DoNotOptimize(map.cols());
    const auto t6 = Clock::now();
    if (!timed) return;
    stereo += Seconds(t1, t2);
    occupancy += Seconds(t2, t3);
    depth += Seconds(t3, t4);
    friction += Seconds(t4, t5);
    terrain += Seconds(t5, t6);
  };
  frame(false);
  for (auto _ : state) frame(true);
  const double n = static_cast<double>(state.iterations());
  state.counters["stereo_ms"] = 1e3 * stereo / n;
  state.counters["occupancy_ms"] = 1e3 * occupancy / n;
  state.counters["depth_ms"] = 1e3 * depth / n;
  state.counters["friction_ms"] = 1e3 * friction / n;
  state.counters["terrain_ms"] = 1e3 * terrain / n;
  state.counters["points"] = static_cast<double>(points);
  state.counters["Hz"] = benchmark::Counter(n, benchmark::Counter::kIsRate);
}
BENCHMARK(BM_PerceptionLoop)
    ->ArgNames({"width", "height", "onnx"})
    ->Args({640, 480, 0})
    ->Args({640, 480, 1})
    ->Args({320, 240, 0})->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace

int main(int argc, char** argv) {
  if (argc > 1 && std::strcmp(argv[1], "--keep-freed-memory") == 0) {
    mallopt(M_MMAP_THRESHOLD, 1 << 30);
    mallopt(M_TRIM_THRESHOLD, 1 << 30);
    argv[1] = argv[0];
    --argc;
    ++argv;
  }
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
