// Footstep planning time on the thesis' ice-patch scenarios (2.4.2): time to the first plan (ARA*, initial
// epsilon 3) and to the optimal plan (epsilon 1), with the project's humanoid and its default transition oracle
// (objective E_COM + heat). The thesis reports a first path in under 1 s and the optimal one within 1 min
// (SBPL's ARA* over IMLE models); the aim here is the optimal plan within 0.5 s on 2 cores.
//
// The oracle is loaded from (or built into) CAIRN_ORACLE_CACHE, default /tmp/cairn-benchmark-oracles.

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <limits>
#include <memory>
#include <string>

#include <benchmark/benchmark.h>

#include <cairn/planning/footstep/plan_footsteps.h>
#include <cairn/planning/locomotion/transition_oracle.h>
#include <cairn/planning/scenarios/footstep_scenario.h>

namespace {

using namespace cairn::planning;

struct Setup {
  std::shared_ptr<const WalkingModel> model;
  std::shared_ptr<const TransitionOracle> oracle;
  BipedGeometry geometry;
};

const Setup& GetSetup() {
  static const Setup setup = [] {
    Setup s;
    s.model = std::make_shared<const WalkingModel>(
        WalkingModel::Load(std::string(CAIRN_SOURCE_DIR) + "/data/robots/cairn_humanoid_walking.yaml"));
    const char* env = std::getenv("CAIRN_ORACLE_CACHE");
    const std::string folder = env != nullptr ? env : "/tmp/cairn-benchmark-oracles";
    std::filesystem::create_directories(folder);
    s.oracle = std::make_shared<const TransitionOracle>(
        TransitionOracle::LoadOrBuild(folder + "/" + s.model->name() + "-ecom_heat.oracle", *s.model,
                                      WalkingObjective::kComWorkPlusHeat, OracleGrid::Default(*s.model),
                                      OracleBuildOptions{}, &std::cerr));
    s.geometry.foot_length = s.model->foot_length();
    s.geometry.foot_width = s.model->foot_width();
    s.geometry.body_half_extents = s.model->body_half_extents();
    s.geometry.body_bottom = s.model->body_box_bottom();
    return s;
  }();
  return setup;
}

void BM_PlanScenario(benchmark::State& state, const std::string& name) {
  const Setup& setup = GetSetup();
  const FootstepScenario scenario =
      FootstepScenario::Load(std::string(CAIRN_SOURCE_DIR) + "/examples/scenarios/" + name + ".yaml");
  const TerrainMap terrain = scenario.BuildTerrain();
  FootstepPlannerOptions options = scenario.planner();
  const char* limit = std::getenv("CAIRN_PLAN_TIME_LIMIT");
  options.search.time_limit = limit != nullptr ? std::atof(limit) : 60.0;
  FootstepPlan plan;
  for (auto _ : state) {
    plan = PlanFootsteps(terrain, scenario.start(), scenario.goal(), *setup.oracle, setup.geometry, options);
    state.SetIterationTime(plan.statistics.plan_seconds);
  }
  state.counters["first_plan_ms"] = 1e3 * plan.statistics.first_plan_seconds;
  state.counters["optimal"] = plan.statistics.epsilon <= 1.0 ? 1 : 0;
  state.counters["expansions"] = static_cast<double>(plan.statistics.expansions);
  state.counters["steps"] = static_cast<double>(plan.steps.size());
  state.counters["energy_J"] = plan.energy;
  state.counters["cost"] = plan.cost;
  state.counters["generated"] = static_cast<double>(plan.statistics.generated);
  state.counters["us_per_expansion"] =
      plan.statistics.expansions > 0 ? 1e6 * plan.statistics.plan_seconds / plan.statistics.expansions : 0.0;
  std::fprintf(stderr, "%s: found %d bound %.6f cost %.9f steps %zu expansions %lld generated %lld %.3f s\n",
               name.c_str(), plan.found, plan.statistics.epsilon, plan.cost, plan.steps.size(),
               static_cast<long long>(plan.statistics.expansions), static_cast<long long>(plan.statistics.generated),
               plan.statistics.plan_seconds);
}

}  // namespace

BENCHMARK_CAPTURE(BM_PlanScenario, flat, std::string("flat"))->UseManualTime()->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK_CAPTURE(BM_PlanScenario, ice_narrow_012, std::string("ice_narrow_012"))
    ->UseManualTime()->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK_CAPTURE(BM_PlanScenario, ice_narrow_006, std::string("ice_narrow_006"))
    ->UseManualTime()->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK_CAPTURE(BM_PlanScenario, ice_wide_006, std::string("ice_wide_006"))
    ->UseManualTime()->Unit(benchmark::kMillisecond)->Iterations(1);

BENCHMARK_CAPTURE(BM_PlanScenario, slope_10, std::string("slope_10"))
    ->UseManualTime()->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK_CAPTURE(BM_PlanScenario, slope_20, std::string("slope_20"))
    ->UseManualTime()->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK_CAPTURE(BM_PlanScenario, slope_25, std::string("slope_25"))
    ->UseManualTime()->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK_CAPTURE(BM_PlanScenario, stairs, std::string("stairs"))
    ->UseManualTime()->Unit(benchmark::kMillisecond)->Iterations(1);

BENCHMARK_MAIN();
