// Output evaluation through a chain of N PassThrough blocks (vector size 3), the measurement Drake publishes for
// its systems framework (about 290 ns per block for three cascaded pass-throughs). Reported as time per block.

#include <memory>

#include <benchmark/benchmark.h>

#include "cairn/systems/framework/diagram_builder.h"
#include "cairn/systems/primitives/pass_through.h"

namespace {

using cairn::systems::Context;
using cairn::systems::Diagram;
using cairn::systems::DiagramBuilder;
using cairn::systems::PassThrough;

std::unique_ptr<Diagram> MakeChain(int length) {
  DiagramBuilder builder;
  PassThrough* previous = nullptr;
  for (int i = 0; i < length; ++i) {
    auto* block = builder.AddSystem<PassThrough>(3);
    if (previous == nullptr) {
      builder.ExportInput(block->get_input_port(), "u");
    } else {
      builder.Connect(*previous, *block);
    }
    previous = block;
  }
  builder.ExportOutput(previous->get_output_port(), "y");
  return builder.Build();
}

void SetPerBlockCounter(benchmark::State& state, int length) {
  state.counters["per_block"] = benchmark::Counter(static_cast<double>(state.iterations()) * length,
                                                   benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

// The input changes every iteration: the change invalidates N cached outputs and Eval recomputes all of them.
void BM_PassThroughChainAfterInputChange(benchmark::State& state) {
  const int length = static_cast<int>(state.range(0));
  const auto diagram = MakeChain(length);
  auto context = diagram->CreateDefaultContext();
  const auto& input = diagram->get_input_port();
  const auto& output = diagram->get_output_port();
  Eigen::VectorXd u = Eigen::Vector3d(1.0, 2.0, 3.0);
  input.FixValue(context.get(), u);
  for (auto _ : state) {
    u[0] += 1.0;
    input.FixValue(context.get(), u);
    benchmark::DoNotOptimize(output.Eval<Eigen::VectorXd>(*context).data());
  }
  SetPerBlockCounter(state, length);
}
BENCHMARK(BM_PassThroughChainAfterInputChange)->Arg(1)->Arg(3)->Arg(10)->Arg(100);

// Nothing changes: Eval returns the cached value.
void BM_PassThroughChainWarmCache(benchmark::State& state) {
  const int length = static_cast<int>(state.range(0));
  const auto diagram = MakeChain(length);
  auto context = diagram->CreateDefaultContext();
  const auto& output = diagram->get_output_port();
  diagram->get_input_port().FixValue(context.get(), Eigen::Vector3d(1.0, 2.0, 3.0));
  output.Eval<Eigen::VectorXd>(*context);
  for (auto _ : state) {
    benchmark::DoNotOptimize(output.Eval<Eigen::VectorXd>(*context).data());
  }
  SetPerBlockCounter(state, length);
}
BENCHMARK(BM_PassThroughChainWarmCache)->Arg(1)->Arg(3)->Arg(10)->Arg(100);

// Caching off: every Eval recomputes the whole chain (what "no cache" costs).
void BM_PassThroughChainCachingDisabled(benchmark::State& state) {
  const int length = static_cast<int>(state.range(0));
  const auto diagram = MakeChain(length);
  auto context = diagram->CreateDefaultContext();
  context->DisableCaching();
  const auto& output = diagram->get_output_port();
  diagram->get_input_port().FixValue(context.get(), Eigen::Vector3d(1.0, 2.0, 3.0));
  for (auto _ : state) {
    benchmark::DoNotOptimize(output.Eval<Eigen::VectorXd>(*context).data());
  }
  SetPerBlockCounter(state, length);
}
BENCHMARK(BM_PassThroughChainCachingDisabled)->Arg(1)->Arg(3)->Arg(10)->Arg(100);

}  // namespace

BENCHMARK_MAIN();
