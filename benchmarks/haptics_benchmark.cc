// Haptic traversability affordances (seed 000, issue 20): the per-frame cost of describing the object in view
// and recalling it against a memory of 1,000 objects (the aim: at most 1 ms together), and of planning the
// antenna's interaction. Clouds are the simulated depth sensor's frames of data set 1 (200 x 150 pixels; a
// Kinect frame has 307,200, but the descriptor's 1 cm down-sampling leaves a few thousand points of either).

#include <vector>

#include <benchmark/benchmark.h>

#include "cairn/perception/haptics/affordance_descriptor.h"
#include "cairn/perception/haptics/haptic_interaction_planner.h"
#include "cairn/perception/haptics/point_cloud_reduction.h"
#include "cairn/perception/haptics/traversability_memory.h"
#include "cairn/perception/haptics/simulation/haptic_affordance_experiment.h"

namespace {

using namespace cairn::perception;

const HapticAffordanceExperiment& Experiment() {
  static const HapticAffordanceExperiment experiment;
  return experiment;
}

// A memory of `size` views of data set 1, labelled by ground truth.
TraversabilityMemory MakeMemory(int size) {
  TraversabilityMemory memory;
  const std::vector<HapticObjectKind> kinds = DataSet1();
  std::vector<AffordanceDescriptor> views;
  for (const HapticObjectKind kind : kinds) {
    for (int a = 0; a < 10; ++a) views.push_back(Experiment().Describe(Experiment().Observe(kind, a)));
  }
  for (int i = 0; i < size; ++i) {
    const std::size_t v = static_cast<std::size_t>(i) % views.size();
    memory.Add(views[v], MakeHapticObject(kinds[v / 10], 0).traversable());
  }
  return memory;
}

void BM_Descriptor(benchmark::State& state) {
  const Eigen::Matrix3Xd points = Experiment().Observe(HapticObjectKind::kShrub, 77);
  for (auto _ : state) benchmark::DoNotOptimize(Experiment().Describe(points));
  state.counters["points"] = static_cast<double>(points.cols());
}
BENCHMARK(BM_Descriptor)->Unit(benchmark::kMicrosecond);

void BM_Recall(benchmark::State& state) {
  const TraversabilityMemory memory = MakeMemory(static_cast<int>(state.range(0)));
  const AffordanceDescriptor observed = Experiment().Describe(Experiment().Observe(HapticObjectKind::kShrub, 77));
  for (auto _ : state) benchmark::DoNotOptimize(memory.Recall(observed));
}
BENCHMARK(BM_Recall)->Arg(100)->Arg(1000)->Arg(10000)->Unit(benchmark::kMicrosecond);

// The per-frame figure of the issue: descriptor + recall against 1,000 memories.
void BM_DescriptorAndRecall1000(benchmark::State& state) {
  const TraversabilityMemory memory = MakeMemory(1000);
  const Eigen::Matrix3Xd points = Experiment().Observe(HapticObjectKind::kShrub, 77);
  for (auto _ : state) benchmark::DoNotOptimize(memory.Recall(Experiment().Describe(points)));
}
BENCHMARK(BM_DescriptorAndRecall1000)->Unit(benchmark::kMicrosecond);

void BM_InteractionPlan(benchmark::State& state) {
  const Eigen::Matrix3Xd points = Experiment().Observe(HapticObjectKind::kShrub, 77);
  const Eigen::Matrix3Xd object = KeepWithinReach(DownsampleByMinDistance(points, 0.01),
                                                  Experiment().options().X_CA.translation(), 1.0);
  const HapticInteractionPlanner planner;
  for (auto _ : state) benchmark::DoNotOptimize(planner.Plan(object, 0.3));
  state.counters["object_points"] = static_cast<double>(object.cols());
}
BENCHMARK(BM_InteractionPlan)->Unit(benchmark::kMicrosecond);

void BM_Gist(benchmark::State& state) {
  const Eigen::Matrix3Xd points = Experiment().Observe(HapticObjectKind::kWall, 3);
  for (auto _ : state) benchmark::DoNotOptimize(CountOccupiedVoxels(points, 0.01));
  state.counters["points"] = static_cast<double>(points.cols());
}
BENCHMARK(BM_Gist)->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
