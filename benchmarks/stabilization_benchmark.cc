// Interpolation and ZMP stabilisation (thesis 2.5.1c): wall time per second of trajectory for the FFT
// compensation and for preview control (and for interpolation alone, "none"), on a whole-body trajectory optimised
// once for eight straight 0.2 m steps on flat ground (t_ds 0.2 s, t_sw 0.6 s), sampled at 200 Hz. Counters: passes
// kept and the RMS ZMP error before and after (mm), so a speed-up that changes the result shows.

#include <memory>
#include <string>

#include <benchmark/benchmark.h>

#include <cairn/multibody/urdf_parser.h>
#include <cairn/planning/stabilization/stabilize_trajectory.h>
#include <cairn/planning/trajectory/optimize_whole_body_trajectory.h>

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

BENCHMARK_CAPTURE(BM_Stabilize, fft, std::string("fft"))->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Stabilize, preview, std::string("preview"))->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Stabilize, none, std::string("none"))->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
