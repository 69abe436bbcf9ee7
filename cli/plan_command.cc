// `cairn plan`: energy- and friction-aware footstep planning with step timing on a scenario file.

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>

#include "cairn/common/atomic_file.h"
#include "cairn/planning/footstep/plan_footsteps.h"
#include "cairn/planning/footstep/refine_footstep_plan.h"
#include "cairn/planning/locomotion/transition_oracle.h"
#include "cairn/planning/locomotion/walking_model.h"
#include "cairn/planning/locomotion/walking_objective.h"
#include "cairn/planning/scenarios/footstep_scenario.h"
#include "command_registry.h"
#include "json.h"
#include "plan_image.h"

namespace cairn::cli {
namespace {

using namespace cairn::planning;

struct PlanArguments {
  std::string scenario;
  std::string objective;
  double time_limit{0.0};
  bool json{false};
  std::string out;
  std::string oracle_cache;
  bool no_refine{false};
};

// $XDG_CACHE_HOME/cairn/oracles, else ~/.cache/cairn/oracles, else a folder in the working directory.
std::string DefaultOracleCache() {
  if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg != nullptr && *xdg != '\0') {
    return std::string(xdg) + "/cairn/oracles";
  }
  if (const char* home = std::getenv("HOME"); home != nullptr && *home != '\0') {
    return std::string(home) + "/.cache/cairn/oracles";
  }
  return ".cairn-cache/oracles";
}

// A one-line progress bar on stderr, redrawn at each whole percent.
class ProgressBar {
 public:
  explicit ProgressBar(std::string label) : label_(std::move(label)) {}
  void Update(std::size_t done, std::size_t total) {
    const int percent = total == 0 ? 100 : static_cast<int>(100 * done / total);
    if (percent == last_percent_) return;
    last_percent_ = percent;
    const int filled = percent / 4;
    std::fprintf(stderr, "\r%s [%s%s] %3d%% (%zu/%zu)", label_.c_str(), std::string(filled, '#').c_str(),
                 std::string(25 - filled, ' ').c_str(), percent, done, total);
    if (done == total) std::fprintf(stderr, "\n");
    std::fflush(stderr);
  }

 private:
  std::string label_;
  int last_percent_{-1};
};

std::string PlanJson(const FootstepScenario& scenario, const FootstepPlan& plan, WalkingObjective objective,
                     double refine_ms) {
  std::ostringstream out;
  out << "{\"scenario\": " << JsonString(scenario.name()) << ", \"objective\": " << JsonString(to_string(objective))
      << ", \"found\": " << JsonBool(plan.found) << ", \"reason\": " << JsonString(plan.reason)
      << ", \"steps\": " << plan.steps.size() << ", \"cost\": " << JsonNumber(plan.cost)
      << ", \"energy_J\": " << JsonNumber(plan.energy) << ", \"duration_s\": " << JsonNumber(plan.duration)
      << ", \"distance_m\": " << JsonNumber(plan.distance) << ", \"max_rcof\": " << JsonNumber(plan.max_rcof)
      << ", \"min_friction_margin\": " << JsonNumber(plan.min_friction_margin)
      << ", \"epsilon\": " << JsonNumber(plan.statistics.epsilon)
      << ", \"expansions\": " << plan.statistics.expansions
      << ", \"plan_ms\": " << JsonNumber(1e3 * plan.statistics.plan_seconds, 4)
      << ", \"first_plan_ms\": " << JsonNumber(1e3 * plan.statistics.first_plan_seconds, 4)
      << ", \"refine_ms\": " << JsonNumber(refine_ms, 4) << ", \"footsteps\": [";
  for (std::size_t k = 0; k < plan.steps.size(); ++k) {
    const PlannedStep& s = plan.steps[k];
    out << (k ? ", " : "") << "{\"side\": " << JsonString(FootSideName(s.side)) << ", \"x\": " << JsonNumber(s.pose.x)
        << ", \"y\": " << JsonNumber(s.pose.y) << ", \"z\": " << JsonNumber(s.pose.z)
        << ", \"theta\": " << JsonNumber(s.pose.theta) << ", \"t_ds\": " << JsonNumber(s.transition.parameters.t_ds)
        << ", \"t_sw\": " << JsonNumber(s.transition.parameters.t_sw)
        << ", \"com_height\": " << JsonNumber(s.transition.parameters.com_height)
        << ", \"energy_J\": " << JsonNumber(s.transition.com_work + s.transition.heat)
        << ", \"rcof\": " << JsonNumber(s.transition.rcof) << ", \"mu_allowed\": " << JsonNumber(s.mu_allowed) << "}";
  }
  out << "]}";
  return out.str();
}

void PrintSummary(const FootstepScenario& scenario, const FootstepPlan& plan, WalkingObjective objective) {
  std::printf("scenario   %s (objective %s)\n", scenario.name().c_str(), to_string(objective));
  if (!plan.found) {
    std::printf("no plan    %s\n", plan.reason.c_str());
    return;
  }
  std::printf("plan       %zu steps, %.2f m, %.1f s, energy %.0f J (cost %.4g), max RCOF %.3f, friction margin %.3f\n",
              plan.steps.size(), plan.distance, plan.duration, plan.energy, plan.cost, plan.max_rcof,
              plan.min_friction_margin);
  std::printf("search     %lld expansions, first plan %.1f ms, %.1f ms in all, bound epsilon %.3g\n",
              static_cast<long long>(plan.statistics.expansions), 1e3 * plan.statistics.first_plan_seconds,
              1e3 * plan.statistics.plan_seconds, plan.statistics.epsilon);
  std::printf("%4s %-5s %7s %7s %6s %6s %6s %6s %6s %8s %6s %6s\n", "step", "side", "x", "y", "z", "theta", "t_ds",
              "t_sw", "com_h", "energy", "rcof", "mu");
  for (std::size_t k = 0; k < plan.steps.size(); ++k) {
    const PlannedStep& s = plan.steps[k];
    std::printf("%4zu %-5s %7.3f %7.3f %6.3f %6.1f %6.2f %6.2f %6.3f %8.1f %6.3f %6.3f\n", k + 1, FootSideName(s.side),
                s.pose.x, s.pose.y, s.pose.z, s.pose.theta * 180.0 / M_PI, s.transition.parameters.t_ds,
                s.transition.parameters.t_sw, s.transition.parameters.com_height,
                s.transition.com_work + s.transition.heat, s.transition.rcof, s.mu_allowed);
  }
}

int Run(const PlanArguments& args) {
  FootstepScenario scenario = FootstepScenario::Load(args.scenario);
  const WalkingObjective objective = ParseWalkingObjective(args.objective.empty() ? scenario.objective() : args.objective);
  FootstepPlannerOptions options = scenario.planner();
  if (args.time_limit > 0.0) options.search.time_limit = args.time_limit;

  const std::string robot = scenario.robot().empty()
                                ? std::string(CAIRN_DATA_DIR) + "/robots/cairn_humanoid_walking.yaml"
                                : scenario.robot();
  const auto model = std::make_shared<const WalkingModel>(WalkingModel::Load(robot));
  const std::string cache = args.oracle_cache.empty() ? DefaultOracleCache() : args.oracle_cache;
  std::filesystem::create_directories(cache);
  const std::string oracle_path = cache + "/" + model->name() + "-" + to_string(objective) + ".oracle";
  OracleBuildOptions build;
  ProgressBar bar("building the transition oracle");
  build.progress = [&bar](std::size_t done, std::size_t total) { bar.Update(done, total); };
  const TransitionOracle oracle =
      TransitionOracle::LoadOrBuild(oracle_path, *model, objective, OracleGrid::Default(*model), build, &std::cerr);

  const TerrainMap terrain = scenario.BuildTerrain();
  BipedGeometry geometry;
  geometry.foot_length = model->foot_length();
  geometry.foot_width = model->foot_width();
  geometry.body_half_extents = model->body_half_extents();
  geometry.body_bottom = model->body_box_bottom();
  FootstepPlan plan = PlanFootsteps(terrain, scenario.start(), scenario.goal(), oracle, geometry, options);
  double refine_ms = 0.0;
  if (!args.no_refine) {
    const auto t0 = std::chrono::steady_clock::now();
    RefineFootstepPlan(*model, objective, &plan);
    refine_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  }

  const std::string json = PlanJson(scenario, plan, objective, refine_ms);
  if (!args.out.empty()) {
    std::filesystem::create_directories(args.out);
    // The picture first: it is the one that can fail (size), and then neither file is replaced.
    WritePlanImage(args.out + "/plan.png", terrain, plan, scenario.goal(), geometry);
    WriteFileAtomically(args.out + "/plan.json", json + "\n");
  }
  if (args.json) {
    std::printf("%s\n", json.c_str());
  } else {
    PrintSummary(scenario, plan, objective);
    if (!args.out.empty()) std::printf("wrote      %s/plan.json, %s/plan.png\n", args.out.c_str(), args.out.c_str());
  }
  return 0;
}

}  // namespace

void RegisterPlanCommand(CommandRegistry* registry) {
  registry->Add("plan", "Plan footsteps and step timing that minimise energy under friction limits (scenario YAML)",
                [](CLI::App& app) -> CommandAction {
                  auto args = std::make_shared<PlanArguments>();
                  app.add_option("--scenario", args->scenario, "Scenario YAML (docs/scenarios.md)")->required();
                  app.add_option("--objective", args->objective, "Step objective (default: the scenario's)")
                      ->check(CLI::IsMember(WalkingObjectiveNames()));
                  app.add_option("--time-limit", args->time_limit, "Planning time budget in seconds")
                      ->check(CLI::PositiveNumber);
                  app.add_flag("--json", args->json, "Print the plan as one JSON object");
                  app.add_option("--out", args->out, "Folder for plan.json and plan.png");
                  app.add_option("--oracle-cache", args->oracle_cache,
                                 "Folder caching transition oracles (default $XDG_CACHE_HOME/cairn/oracles)");
                  app.add_flag("--no-refine", args->no_refine, "Keep the table's step parameters (skip SLSQP)");
                  return [args] { return Run(*args); };
                });
}

}  // namespace cairn::cli
