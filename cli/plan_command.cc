// `cairn plan`: energy- and friction-aware footstep planning with step timing on a scenario file.

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <limits>
#include <memory>
#include <optional>
#include <string>

#include "cairn/common/atomic_output_directory.h"
#include "cairn/common/json_writer.h"
#include "cairn/common/number_text.h"
#include "cairn/planning/footstep/plan_footsteps.h"
#include "cairn/planning/footstep/refine_footstep_plan.h"
#include "cairn/planning/footstep/time_limit_reached.h"
#include "cairn/planning/locomotion/transition_oracle.h"
#include "cairn/planning/locomotion/walking_model.h"
#include "cairn/planning/locomotion/walking_objective.h"
#include "cairn/planning/scenarios/footstep_scenario.h"
#include "choice_option.h"
#include "command_registry.h"
#include "data_directory.h"
#include "file_checks.h"
#include "numeric_option.h"
#include "oracle_cache.h"
#include "plan_image.h"
#include "whole_body_output.h"
#include "progress_bar.h"

namespace cairn::cli {
namespace {

using namespace cairn::planning;

struct PlanArguments {
  std::string scenario;
  std::string objective;
  double time_limit{0.0};
  bool json{false};
  std::string out;
  OracleChoice oracle;
  bool no_refine{false};
  bool whole_body{false};
};

// The files `--out` holds; the folder is replaced as a whole (AtomicOutputDirectory).
bool IsPlanOutput(const std::string& name) {
  return name == "plan.json" || name == "plan.png" || name == "trajectory.json" || name == "trajectory.png";
}

// The plan as JSON. With `with_wall_times` it also holds the search's and the refinement's wall-clock times
// (`plan_ms`, `first_plan_ms`, `refine_ms`): the report on stdout has them, plan.json does not, so that the same
// scenario gives the same bytes on every run and machine.
std::string PlanJson(const FootstepScenario& scenario, const FootstepPlan& plan, WalkingObjective objective,
                     double refine_ms, bool with_wall_times, const std::string& oracle_source = "") {
  // Without a plan its measures do not exist, nor a first-plan time without a first plan: the writer gets NaN
  // (JSON null) instead of the zeros and the -1 placeholder the struct holds.
  const double none = std::numeric_limits<double>::quiet_NaN();
  const auto measure = [&](double x) { return plan.found ? x : none; };
  const double first_plan_ms =
      plan.statistics.first_plan_seconds >= 0.0 ? 1e3 * plan.statistics.first_plan_seconds : none;
  const JsonWriter::NumberFormat ms = JsonWriter::Significant(4);
  JsonWriter json;
  json.BeginObject().Key("scenario").String(scenario.name()).Key("objective").String(to_string(objective));
  if (!oracle_source.empty()) json.Key("oracle_source").String(oracle_source);
  json.Key("found").Bool(plan.found).Key("reason").String(plan.reason).Key("steps").Integer(plan.steps.size());
  json.Key("cost").Number(measure(plan.cost)).Key("energy_J").Number(measure(plan.energy));
  json.Key("duration_s").Number(measure(plan.duration));
  json.Key("distance_m").Number(measure(plan.distance)).Key("max_rcof").Number(measure(plan.max_rcof));
  json.Key("min_friction_margin").Number(measure(plan.min_friction_margin));
  json.Key("epsilon").Number(measure(plan.statistics.epsilon));
  json.Key("expansions").Integer(plan.statistics.expansions);
  if (with_wall_times) {
    json.Key("plan_ms").Number(1e3 * plan.statistics.plan_seconds, ms);
    json.Key("first_plan_ms").Number(first_plan_ms, ms);
    json.Key("refine_ms").Number(refine_ms, ms);
  }
  json.Key("footsteps").BeginArray();
  for (const PlannedStep& s : plan.steps) {
    json.BeginObject().Key("side").String(FootSideName(s.side)).Key("x").Number(s.pose.x).Key("y").Number(s.pose.y);
    json.Key("z").Number(s.pose.z).Key("theta").Number(s.pose.theta);
    json.Key("t_ds").Number(s.transition.parameters.t_ds).Key("t_sw").Number(s.transition.parameters.t_sw);
    json.Key("com_height").Number(s.transition.parameters.com_height);
    json.Key("energy_J").Number(s.transition.com_work + s.transition.heat).Key("rcof").Number(s.transition.rcof);
    json.Key("mu_allowed").Number(s.mu_allowed).EndObject();
  }
  json.EndArray().EndObject();
  return json.text();
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
  CheckInputFile("--scenario", args.scenario, "a scenario YAML file");
  if (!args.oracle.grid.empty()) CheckInputFile("--oracle-grid", args.oracle.grid, "an oracle grid YAML file");
  FootstepScenario scenario = FootstepScenario::Load(args.scenario);
  OracleChoice oracle_choice = args.oracle;
  oracle_choice.Resolve(scenario);
  const WalkingObjective objective =
      ParseWalkingObjective(args.objective.empty() ? scenario.objective() : args.objective);
  FootstepPlannerOptions options = scenario.planner();
  if (args.time_limit > 0.0) options.search.time_limit = args.time_limit;
  // The time limit covers the terrain's rasterisation and the planning (the heuristic's precomputation and the
  // search), not the transition oracle: that is loaded from the cache, or built once for every later run.
  using Clock = std::chrono::steady_clock;
  const double time_limit = options.search.time_limit;
  const Clock::time_point start = Clock::now();
  const auto seconds_since_start = [start] { return std::chrono::duration<double>(Clock::now() - start).count(); };
  const Clock::time_point deadline =
      start + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(time_limit));
  std::optional<TerrainMap> terrain;
  FootstepPlan plan;
  try {
    terrain.emplace(scenario.BuildTerrain(deadline));
  } catch (const TimeLimitReached& error) {
    plan.reason = "no plan within the time limit of " + FormatShort(time_limit) + " s: " + error.what() +
                  "; raise the limit (--time-limit, or the scenario's planner time_limit), crop the terrain to the "
                  "region around start and goal, or coarsen its resolution";
  }
  const double terrain_seconds = seconds_since_start();
  // The search gets what the rasterisation left; when nothing is left the time ran out there.
  const double remaining = time_limit - terrain_seconds;
  if (terrain && !(remaining > 0.0)) {
    plan.reason = "no plan within the time limit of " + FormatShort(time_limit) +
                  " s: rasterising the terrain took all of it; raise the limit (--time-limit, or the scenario's "
                  "planner time_limit) or coarsen the terrain's resolution";
  }
  if (!plan.reason.empty()) {
    // A result, not a failure: plan.json (there is no terrain to draw) and the summary say why there is no plan.
    plan.statistics.plan_seconds = terrain_seconds;
    if (!args.out.empty()) {
      AtomicOutputDirectory out(args.out, IsPlanOutput);
      out.WriteFile("plan.json", PlanJson(scenario, plan, objective, 0.0, false) + "\n");
      out.Commit();
    }
    if (args.json) {
      std::printf("%s\n", PlanJson(scenario, plan, objective, 0.0, true).c_str());
    } else {
      PrintSummary(scenario, plan, objective);
      if (!args.out.empty()) std::printf("wrote      %s/plan.json\n", args.out.c_str());
    }
    return 0;
  }
  options.search.time_limit = remaining;
  // Before the oracle and the search: an --out that cannot be written, or a picture too large, fails now
  // instead of after the whole time limit.
  std::optional<AtomicOutputDirectory> out;
  if (!args.out.empty()) {
    PlanImageSize(*terrain);
    out.emplace(args.out, IsPlanOutput);
  }

  const std::string robot = scenario.robot().empty()
                                ? DataDirectory() + "/robots/cairn_humanoid_walking.yaml"
                                : scenario.robot();
  CheckInputFile("the scenario's robot", robot, "a walking-model YAML file");
  const auto model = std::make_shared<const WalkingModel>(WalkingModel::Load(robot));
  const TransitionOracle oracle = LoadChosenOracle(oracle_choice, model, objective);

  BipedGeometry geometry;
  geometry.foot_length = model->foot_length();
  geometry.foot_width = model->foot_width();
  geometry.body_half_extents = model->body_half_extents();
  geometry.body_bottom = model->body_box_bottom();
  plan = PlanFootsteps(*terrain, scenario.start(), scenario.goal(), oracle, geometry, options);
  double refine_ms = 0.0;
  // The refinement optimises the analytic model's cost: a plan priced by the plant keeps the plant's timings.
  if (!args.no_refine && !oracle_choice.measured()) {
    const auto t0 = std::chrono::steady_clock::now();
    RefineFootstepPlan(*model, objective, &plan);
    refine_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  }

  const int whole_body =
      args.whole_body ? RunWholeBody(scenario, plan, terrain ? &*terrain : nullptr, args.json, out ? &*out : nullptr)
                      : 0;
  if (out) {
    out->WriteFile("plan.png", PlanImagePng(*terrain, plan, scenario.goal(), geometry));
    out->WriteFile("plan.json", PlanJson(scenario, plan, objective, refine_ms, false, oracle.source()) + "\n");
    out->Commit();
  }
  if (args.json) {
    std::printf("%s\n", PlanJson(scenario, plan, objective, refine_ms, true, oracle.source()).c_str());
  } else {
    PrintSummary(scenario, plan, objective);
    std::printf("oracle     %s\n", oracle.description().c_str());
    if (out) std::printf("wrote      %s/plan.json, %s/plan.png\n", args.out.c_str(), args.out.c_str());
  }
  return whole_body;
}

}  // namespace

void RegisterPlanCommand(CommandRegistry* registry) {
  registry->Add("plan", "Plan footsteps and step timing that minimise energy under friction limits (scenario YAML)",
                [](CLI::App& app) -> CommandAction {
                  auto args = std::make_shared<PlanArguments>();
                  app.add_option("--scenario", args->scenario, "Scenario YAML (docs/scenarios.md)")->required();
                  AddChoiceOption(app, "--objective", &args->objective, "Step objective (default: the scenario's)",
                                  WalkingObjectiveNames());
                  AddNumberOption(app, "--time-limit", &args->time_limit,
                                  "Planning time budget in seconds (default: the scenario's)",
                                  NumberRange::AboveAtMost(0.0, 86400.0))
                      ->default_str("");
                  app.add_flag("--json", args->json, "Print the plan as one JSON object");
                  app.add_option("--out", args->out, "Folder for plan.json and plan.png (replaced as a whole)");
                  AddOracleOptions(app, &args->oracle);
                  app.add_flag("--no-refine", args->no_refine, "Keep the table's step parameters (skip SLSQP)");
                  app.add_flag("--whole-body", args->whole_body,
                               "Also optimise the whole-body trajectory (trajectory.json, trajectory.png in --out)");
                  return [args] { return Run(*args); };
                });
}

}  // namespace cairn::cli
