// Interpolation and ZMP stabilisation (thesis 2.5.1c): wall time per second of trajectory for the FFT
// compensation and for preview control (and for interpolation alone, "none"), on a whole-body trajectory optimised
// once for eight straight 0.2 m steps on flat ground (t_ds 0.2 s, t_sw 0.6 s), sampled at 200 Hz. Counters: passes
// kept and the RMS ZMP error before and after (mm), so a speed-up that changes the result shows.
//
// BM_PlantPlaysTheReference: wall time per simulated second of the walk diagram's last blocks (Stabilizer ->
// StabilizedReferencePlayer [-> BalanceFeedback] -> HumanoidPlant, 1 ms plant steps) on that trajectory with the
// walking options: the cost that the Stabilizer's per-step check, its dense reference and (`feedback`) the
// capture-point feedback add to each plant step.
//
// BM_PlantGait: wall time of one sample of the `plant` oracle source (issue 21): a level periodic gait of six 0.1 m
// steps and a closing step (t_ds 0.5 s, t_sw 1.2 s) planned, optimised, stabilised and walked by PlantGaitSampler,
// with the stages' shares as counters. Its peer is the thesis' sweep: about 12,600 gaits in "around 2 days" of ODE
// (2.3.3), 13.7 s per gait.
//
// BM_PipelineGait: the same gait as one sample of the `pipeline` source (PlantGaitSampler::MeasurePlanned: planned,
// optimised and stabilised, not walked), so the two sources' costs per gait are read side by side.

#include <memory>
#include <string>
#include <vector>

#include <benchmark/benchmark.h>

#include <cairn/multibody/plant/humanoid_plant.h>
#include <cairn/multibody/plant/joint_pd_controller.h>
#include <cairn/multibody/urdf_parser.h>
#include <cairn/planning/stabilization/stabilize_trajectory.h>
#include <cairn/planning/stabilization/stabilized_reference_player.h>
#include <cairn/planning/stabilization/stabilizer.h>
#include <cairn/planning/trajectory/optimize_whole_body_trajectory.h>
#include <cairn/planning/walk/balance_feedback.h>
#include <cairn/planning/walk/plant_gait_sampler.h>
#include <cairn/systems/analysis/simulator.h>
#include <cairn/systems/framework/diagram_builder.h>
#include <cairn/systems/primitives/constant_value_source.h>

namespace {

using namespace cairn;
using namespace cairn::planning;

std::shared_ptr<const multibody::Model> Robot() {
  static const auto model = [] {
    multibody::UrdfOptions options;
    options.floating_base = true;
    return std::make_shared<const multibody::Model>(
        multibody::ParseUrdfFile(std::string(CAIRN_SOURCE_DIR) + "/data/robots/cairn_humanoid.urdf", options));
  }();
  return model;
}

const WholeBodyTrajectory& Trajectory() {
  static const WholeBodyTrajectory trajectory = [] {
    FootstepPlan plan;
    plan.found = true;
    plan.start.left = {0.0, 0.1, 0.0, 0.0};
    plan.start.right = {0.0, -0.1, 0.0, 0.0};
    plan.first_side = FootSide::kRight;
    double x[2] = {0.0, 0.0};
    for (int k = 0; k < 8; ++k) {
      PlannedStep step;
      step.side = k % 2 == 0 ? FootSide::kRight : FootSide::kLeft;
      const int self = step.side == FootSide::kLeft ? 0 : 1;
      x[self] = k == 7 ? x[1 - self] : x[1 - self] + 0.2;
      step.pose = {x[self], self == 0 ? 0.1 : -0.1, 0.0, 0.0};
      step.transition.feasible = true;
      step.transition.parameters = {0.2, 0.6, 0.8};
      step.transition.duration = 0.8;
      plan.steps.push_back(step);
    }
    plan.UpdateTotals();
    return OptimizeWholeBodyTrajectory(Robot(), plan, {}, TrajectoryOptimizerOptions());
  }();
  return trajectory;
}

void BM_Stabilize(benchmark::State& state, const std::string& method) {
  const WholeBodyTrajectory& trajectory = Trajectory();
  if (!trajectory.found) {
    state.SkipWithError(("the trajectory was not optimised: " + trajectory.report.message).c_str());
    return;
  }
  StabilizerOptions options;
  options.method = method;
  StabilizedTrajectory result;
  for (auto _ : state) {
    result = StabilizeTrajectory(Robot(), trajectory, options);
    benchmark::DoNotOptimize(result.q.data());
  }
  const double seconds_of_motion = result.duration();
  state.counters["s_per_s_of_motion"] = benchmark::Counter(
      static_cast<double>(state.iterations()) * seconds_of_motion,
      benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
  state.counters["passes"] = result.report.iterations;
  state.counters["rms_before_mm"] = 1000.0 * result.report.rms_error_before;
  state.counters["rms_after_mm"] = 1000.0 * result.report.rms_error_after;
}

void BM_PlantPlaysTheReference(benchmark::State& state, bool feedback) {
  const WholeBodyTrajectory& trajectory = Trajectory();
  if (!trajectory.found) {
    state.SkipWithError(("the trajectory was not optimised: " + trajectory.report.message).c_str());
    return;
  }
  const auto robot = Robot();
  const std::string data = std::string(CAIRN_SOURCE_DIR) + "/data/robots/";
  const auto controller = multibody::JointPdController::Load(*robot, data + "cairn_humanoid_control.yaml");
  multibody::TerrainBox ground;
  ground.name = "floor";
  ground.size = Eigen::Vector3d(10.0, 10.0, 1.0);
  ground.X_WB = multibody::Pose(Eigen::Matrix3d::Identity(), Eigen::Vector3d(0.0, 0.0, -0.5));
  ground.friction = 0.8;
  multibody::HumanoidPlantOptions plant_options;
  plant_options.stop_on_fall = false;
  systems::DiagramBuilder builder;
  auto* source = builder.AddNamedSystem<systems::ConstantValueSource<WholeBodyTrajectory>>("trajectory", trajectory);
  auto* stabilizer = builder.AddNamedSystem<Stabilizer>("stabilizer", robot, WalkingStabilizerOptions("fft"));
  auto* player = builder.AddNamedSystem<StabilizedReferencePlayer>("player", robot);
  auto* plant = builder.AddNamedSystem<multibody::HumanoidPlant>(
      "plant", *robot, std::vector<multibody::TerrainBox>{ground}, controller, trajectory.waypoints.front().q,
      plant_options);
  builder.Connect(source->GetOutputPort("y0"), stabilizer->get_trajectory_input_port());
  builder.Connect(stabilizer->get_reference_output_port(), player->get_reference_input_port());
  if (feedback) {
    auto* balance = builder.AddNamedSystem<BalanceFeedback>("balance", robot);
    builder.Connect(player->get_reference_output_port(), balance->get_reference_input_port());
    builder.Connect(plant->GetOutputPort("state"), balance->get_state_input_port());
    builder.Connect(plant->GetOutputPort("contacts"), balance->get_contacts_input_port());
    builder.Connect(balance->get_reference_output_port(), plant->GetInputPort("reference"));
  } else {
    builder.Connect(player->get_reference_output_port(), plant->GetInputPort("reference"));
  }
  const auto diagram = builder.Build();
  const double simulated = 1.0;
  for (auto _ : state) {
    state.PauseTiming();
    systems::Simulator simulator(*diagram);
    simulator.Initialize();  // the Stabilizer's initialization event stabilises the trajectory (not timed)
    systems::Context& root = simulator.get_mutable_context();
    const auto& reference = stabilizer->get_reference_output_port().Eval<StabilizedTrajectory>(
        diagram->GetSubsystemContext(*stabilizer, root));
    Eigen::VectorXd x(robot->nq() + robot->nv());
    x << reference.q.front(), reference.v.front();
    diagram->GetMutableSubsystemContext(*plant, &root).SetDiscreteState(0, x);
    state.ResumeTiming();
    benchmark::DoNotOptimize(simulator.AdvanceTo(simulated));
  }
  state.counters["wall_s_per_simulated_s"] = benchmark::Counter(
      static_cast<double>(state.iterations()) * simulated, benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

void BM_PlantGait(benchmark::State& state) {
  const auto controller = std::make_shared<const multibody::JointPdController>(multibody::JointPdController::Load(
      *Robot(), std::string(CAIRN_SOURCE_DIR) + "/data/robots/cairn_humanoid_control.yaml"));
  const auto walking_model = std::make_shared<const WalkingModel>(
      WalkingModel::Load(std::string(CAIRN_SOURCE_DIR) + "/data/robots/cairn_humanoid_walking.yaml"));
  const PlantGaitSampler sampler(walking_model, Robot(), controller, WalkingObjective::kComWorkPlusHeat);
  PeriodicGait gait;
  gait.displacement = {0.1, 0.2, 0.0, 0.0};
  gait.parameters = {0.5, 1.2, 0.7};
  GaitMeasurement m;
  double trajectory = 0.0, stabilizer = 0.0, plant = 0.0;
  for (auto _ : state) {
    m = sampler.Measure(gait);
    trajectory += m.seconds.trajectory;
    stabilizer += m.seconds.stabilizer;
    plant += m.plant_seconds;
  }
  if (!m.feasible) state.SkipWithError(("the gait was not walked: " + m.reason).c_str());
  const double n = static_cast<double>(state.iterations());
  state.counters["trajectory_s"] = trajectory / n;
  state.counters["stabilizer_s"] = stabilizer / n;
  state.counters["plant_s"] = plant / n;
  state.counters["simulated_s"] = m.duration;
  state.counters["com_work_J"] = m.com_work;
}

void BM_PipelineGait(benchmark::State& state) {
  const auto controller = std::make_shared<const multibody::JointPdController>(multibody::JointPdController::Load(
      *Robot(), std::string(CAIRN_SOURCE_DIR) + "/data/robots/cairn_humanoid_control.yaml"));
  const auto walking_model = std::make_shared<const WalkingModel>(
      WalkingModel::Load(std::string(CAIRN_SOURCE_DIR) + "/data/robots/cairn_humanoid_walking.yaml"));
  const PlantGaitSampler sampler(walking_model, Robot(), controller, WalkingObjective::kSquaredTorque);
  PeriodicGait gait;
  gait.displacement = {0.1, 0.2, 0.0, 0.0};
  gait.parameters = {0.5, 1.2, 0.7};
  GaitMeasurement m;
  double trajectory = 0.0, stabilizer = 0.0;
  for (auto _ : state) {
    m = sampler.MeasurePlanned(gait);
    trajectory += m.seconds.trajectory;
    stabilizer += m.seconds.stabilizer;
  }
  if (!m.feasible) state.SkipWithError(("the gait was not planned: " + m.reason).c_str());
  const double n = static_cast<double>(state.iterations());
  state.counters["trajectory_s"] = trajectory / n;
  state.counters["stabilizer_s"] = stabilizer / n;
  state.counters["torque_cost"] = m.torque_cost;
  state.counters["com_work_J"] = m.com_work;
}

BENCHMARK_CAPTURE(BM_Stabilize, fft, std::string("fft"))->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Stabilize, preview, std::string("preview"))->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Stabilize, none, std::string("none"))->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_PlantPlaysTheReference, open_loop, false)->Unit(benchmark::kMillisecond)->Iterations(3);
BENCHMARK_CAPTURE(BM_PlantPlaysTheReference, feedback, true)->Unit(benchmark::kMillisecond)->Iterations(3);
BENCHMARK(BM_PlantGait)->Unit(benchmark::kMillisecond)->Iterations(3);
BENCHMARK(BM_PipelineGait)->Unit(benchmark::kMillisecond)->Iterations(3);

}  // namespace

BENCHMARK_MAIN();
