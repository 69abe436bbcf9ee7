// Locomotion oracles (issue 7): the precompute of the default transition table, one OptimizeTransition, and a
// table lookup. The thesis (2.4.1) learned its models from ~12,600 simulated patterns and precomputed 18,491
// transitions in about 2 h; the aim here is the default table within 60 s on 2 cores.
//
// Before the benchmarks run, main() prints the cheapest forward walking on level ground (objective ecom_heat)
// for mu = 1.0, 0.12 and 0.06: cost per metre of forward progress and the chosen step, the numbers behind the
// thesis' ice-patch decisions (Table 2.1, Fig. 2.7).

#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <random>

#include <benchmark/benchmark.h>

#include "cairn/planning/locomotion/transition_optimizer.h"
#include "cairn/planning/locomotion/transition_oracle.h"
#include "cairn/planning/locomotion/walking_model.h"

namespace {

using cairn::planning::OptimizeTransition;
using cairn::planning::OracleBuildOptions;
using cairn::planning::OracleGrid;
using cairn::planning::StepDisplacement;
using cairn::planning::TransitionCost;
using cairn::planning::TransitionOracle;
using cairn::planning::WalkingModel;
using cairn::planning::WalkingObjective;

const WalkingModel& Model() {
  static const WalkingModel model =
      WalkingModel::Load(std::string(CAIRN_SOURCE_DIR) + "/data/robots/cairn_humanoid_walking.yaml");
  return model;
}

std::unique_ptr<TransitionOracle>& SharedOracle() {
  static std::unique_ptr<TransitionOracle> oracle;
  return oracle;
}

void BM_OraclePrecomputeDefaultGrid(benchmark::State& state) {
  const OracleGrid grid = OracleGrid::Default(Model());
  OracleBuildOptions options;
  options.num_threads = static_cast<int>(state.range(0));
  for (auto _ : state) {
    SharedOracle() = std::make_unique<TransitionOracle>(
        TransitionOracle::Build(Model(), WalkingObjective::kComWorkPlusHeat, grid, options));
  }
  state.counters["entries"] = static_cast<double>(SharedOracle()->num_entries());
  state.counters["feasible"] = static_cast<double>(SharedOracle()->num_feasible());
  state.counters["seconds"] = SharedOracle()->build_seconds();
  state.counters["threads"] = static_cast<double>(options.num_threads);
}
BENCHMARK(BM_OraclePrecomputeDefaultGrid)->Arg(2)->Iterations(1)->Unit(benchmark::kSecond)->UseRealTime();

void BM_OptimizeTransition(benchmark::State& state) {
  const StepDisplacement d{0.25, 0.2, 0.0, 0.0};
  for (auto _ : state) {
    benchmark::DoNotOptimize(OptimizeTransition(Model(), d, 0.12, WalkingObjective::kComWorkPlusHeat));
  }
}
BENCHMARK(BM_OptimizeTransition)->Unit(benchmark::kMillisecond);

void BM_OracleLookup(benchmark::State& state) {
  if (!SharedOracle()) {
    state.SkipWithError("run BM_OraclePrecomputeDefaultGrid first (same filter)");
    return;
  }
  const TransitionOracle& oracle = *SharedOracle();
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<StepDisplacement> steps(1024);
  std::vector<double> mus(1024);
  for (std::size_t i = 0; i < steps.size(); ++i) {
    steps[i] = StepDisplacement{0.35 * u(rng), 0.17 + 0.13 * u(rng), -0.15 + 0.3 * u(rng), 0.52 * u(rng)};
    mus[i] = 0.04 + u(rng);
  }
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(oracle.Evaluate(steps[i], mus[i]));
    i = (i + 1) % steps.size();
  }
}
BENCHMARK(BM_OracleLookup)->Unit(benchmark::kNanosecond);

// Cheapest cost per metre of forward progress on level ground: min over dx, dy of cost / dx.
void PrintForwardWalking() {
  std::printf("Forward walking on level ground, objective ecom_heat (cost per metre = cost / dx):\n");
  std::printf("%6s %10s %6s %6s %7s %7s %7s %8s %8s %8s\n", "mu", "J/m", "dx", "dy", "t_ds", "t_sw", "h", "rcof",
              "E_COM", "heat");
  for (double mu : {1.0, 0.12, 0.06}) {
    TransitionCost best;
    double best_per_metre = INFINITY, best_dx = 0.0, best_dy = 0.0;
    for (int i = 1; i <= 7; ++i) {
      for (double dy : {0.17, 0.20, 0.25}) {
        const double dx = i * 0.05;
        const TransitionCost c = OptimizeTransition(Model(), {dx, dy, 0.0, 0.0}, mu, WalkingObjective::kComWorkPlusHeat);
        if (c.feasible && c.cost / dx < best_per_metre) {
          best = c;
          best_per_metre = c.cost / dx;
          best_dx = dx;
          best_dy = dy;
        }
      }
    }
    std::printf("%6.2f %10.1f %6.2f %6.2f %7.3f %7.3f %7.3f %8.4f %8.2f %8.2f\n", mu, best_per_metre, best_dx, best_dy,
                best.parameters.t_ds, best.parameters.t_sw, best.parameters.com_height, best.rcof, best.com_work,
                best.heat);
  }
  std::fflush(stdout);
}

}  // namespace

int main(int argc, char** argv) {
  PrintForwardWalking();
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
