// Whole-body trajectory optimisation (thesis 2.5.1b, problem 2.9) on footstep plans of the thesis' scenarios:
// seconds per stance for the whole plan as one NLP and for a receding window of 2 stances, with Ipopt given the
// Hessian (differences of the analytic Jacobians, declared by every term) or L-BFGS, in the same run. Counters:
// problem size (variables, constraint rows, Jacobian and declared Hessian nonzeros of the largest problem),
// Ipopt iterations and whether the solve succeeded. Anchor: the thesis' 1.6 s per stance (trajopt's SQP against
// meshes, 6.3.2); aim: 0.1 s per stance on one core.
//
// Footstep plans come from the default oracle, loaded from (or built into) CAIRN_ORACLE_CACHE (default
// /tmp/cairn-benchmark-oracles), with a 200 000-expansion budget so the plans do not depend on the machine.

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <limits>
#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <benchmark/benchmark.h>

#include <Eigen/Geometry>

#include <cairn/common/number_text.h>

#include <cairn/multibody/urdf_parser.h>
#include <cairn/planning/footstep/plan_footsteps.h>
#include <cairn/planning/locomotion/transition_oracle.h>
#include <cairn/planning/scenarios/footstep_scenario.h>
#include <cairn/planning/trajectory/environment_from_obstacles.h>
#include <cairn/planning/trajectory/optimize_whole_body_trajectory.h>

namespace {

using namespace cairn;
using namespace cairn::planning;

struct Scenario {
  FootstepPlan plan;
  std::vector<EnvironmentBox> environment;
};

std::shared_ptr<const multibody::Model> Robot() {
  static const auto model = [] {
    multibody::UrdfOptions options;
    options.floating_base = true;
    return std::make_shared<const multibody::Model>(
        multibody::ParseUrdfFile(std::string(CAIRN_SOURCE_DIR) + "/data/robots/cairn_humanoid.urdf", options));
  }();
  return model;
}

const Scenario& GetScenario(const std::string& name) {
  static std::map<std::string, Scenario> cache;
  auto it = cache.find(name);
  if (it != cache.end()) return it->second;
  static const auto walking = std::make_shared<const WalkingModel>(
      WalkingModel::Load(std::string(CAIRN_SOURCE_DIR) + "/data/robots/cairn_humanoid_walking.yaml"));
  static const auto oracle = [] {
    const char* env = std::getenv("CAIRN_ORACLE_CACHE");
    const std::string folder = env != nullptr ? env : "/tmp/cairn-benchmark-oracles";
    std::filesystem::create_directories(folder);
    return std::make_shared<const TransitionOracle>(TransitionOracle::LoadOrBuild(
        folder + "/" + walking->name() + "-ecom_heat.oracle", *walking, WalkingObjective::kComWorkPlusHeat,
        OracleGrid::Default(*walking), OracleBuildOptions{}, &std::cerr));
  }();
  BipedGeometry geometry;
  geometry.foot_length = walking->foot_length();
  geometry.foot_width = walking->foot_width();
  geometry.body_half_extents = walking->body_half_extents();
  geometry.body_bottom = walking->body_box_bottom();
  const FootstepScenario scenario =
      FootstepScenario::Load(std::string(CAIRN_SOURCE_DIR) + "/examples/scenarios/" + name + ".yaml");
  FootstepPlannerOptions options = scenario.planner();
  options.search.time_limit = std::numeric_limits<double>::infinity();
  options.search.max_expansions = 200000;
  Scenario s;
  s.plan = PlanFootsteps(scenario.BuildTerrain(), scenario.start(), scenario.goal(), *oracle, geometry, options);
  s.environment = EnvironmentFromObstacles(scenario.obstacles());
  return cache.emplace(name, std::move(s)).first->second;
}

// The rotation of the floating base between consecutive waypoints, degrees: largest and mean.
std::pair<double, double> WaistRotation(const WholeBodyTrajectory& trajectory) {
  double largest = 0.0, sum = 0.0;
  for (std::size_t i = 1; i < trajectory.waypoints.size(); ++i) {
    const Eigen::VectorXd& a = trajectory.waypoints[i - 1].q;
    const Eigen::VectorXd& b = trajectory.waypoints[i].q;
    const double angle =
        Eigen::Quaterniond(a(3), a(4), a(5), a(6)).angularDistance(Eigen::Quaterniond(b(3), b(4), b(5), b(6))) *
        180.0 / M_PI;
    largest = std::max(largest, angle);
    sum += angle;
  }
  const auto segments = static_cast<double>(std::max<std::size_t>(1, trajectory.waypoints.size() - 1));
  return {largest, sum / segments};
}

void BM_WholeBody(benchmark::State& state, const std::string& name, const std::string& hessian, int window,
                  double rotation_weight) {
  const Scenario& scenario = GetScenario(name);
  if (!scenario.plan.found) {
    state.SkipWithError(("no footstep plan for " + name + ": " + scenario.plan.reason).c_str());
    return;
  }
  TrajectoryOptimizerOptions options;
  options.hessian = hessian;
  options.window_stances = window;
  options.base_rotation_smoothness_weight = rotation_weight;
  WholeBodyTrajectory trajectory;
  for (auto _ : state) {
    trajectory = OptimizeWholeBodyTrajectory(Robot(), scenario.plan, scenario.environment, options);
    benchmark::DoNotOptimize(trajectory.report.objective);
  }
  const double stances = static_cast<double>(scenario.plan.steps.size() + 1);
  state.counters["s_per_stance"] = trajectory.report.seconds / stances;
  state.counters["stances"] = stances;
  state.counters["variables"] = trajectory.report.num_variables;
  state.counters["constraints"] = trajectory.report.num_constraints;
  state.counters["jacobian_nnz"] = trajectory.report.jacobian_nonzeros;
  state.counters["hessian_nnz"] = trajectory.report.hessian_nonzeros;
  state.counters["iterations"] = trajectory.report.iterations;
  state.counters["windows"] = trajectory.report.windows;
  state.counters["success"] = trajectory.report.success ? 1.0 : 0.0;
  state.counters["torque_cost"] = trajectory.report.torque_cost;
  state.counters["objective"] = trajectory.report.objective;
  const auto [largest, mean] = WaistRotation(trajectory);
  state.counters["waist_deg_max"] = largest;
  state.counters["waist_deg_mean"] = mean;
  if (!trajectory.report.success) std::cerr << name << " (" << hessian << "): " << trajectory.report.message << "\n";
}

void Register() {
  // Whole plan with each Hessian, a receding window of 2 stances, and both with the waist-orientation smoothness
  // term (base_rotation_smoothness_weight) at 0.1, 1 and 10.
  struct Configuration {
    std::string hessian;
    int window;
    double rotation_weight;
  };
  const std::vector<Configuration> configurations = {
      {"gauss-newton", 0, 0.0}, {"exact", 0, 0.0}, {"limited-memory", 0, 0.0}, {"gauss-newton", 2, 0.0},
      {"exact", 2, 0.0},        {"exact", 2, 0.1}, {"exact", 2, 1.0},          {"exact", 2, 10.0},
      {"exact", 0, 1.0},        {"limited-memory", 2, 0.0}};
  // The flat 3 m plan and the thesis' three ice plans (2.4.2: mu 0.06 on a narrow and a wide patch, mu 0.12).
  for (const std::string name : {"flat", "ice_narrow_006", "ice_narrow_012", "ice_wide_006"}) {
    for (const Configuration& c : configurations) {
      const std::string label = "BM_WholeBody/" + name + "/" + c.hessian + "/window:" + std::to_string(c.window) +
                                "/rotation_weight:" + cairn::FormatShort(c.rotation_weight);
      benchmark::RegisterBenchmark(label.c_str(), BM_WholeBody, name, c.hessian, c.window, c.rotation_weight)
          ->Unit(benchmark::kSecond)
          ->Iterations(1);
    }
  }
}

}  // namespace

int main(int argc, char** argv) {
  Register();
  benchmark::Initialize(&argc, argv);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
