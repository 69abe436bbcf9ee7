// `cairn walk`: the footstep plan, its whole-body trajectory and its stabilised reference walked by the humanoid in
// the Bullet plant on the scenario's terrain with its true friction -- one diagram (planning/walk) run by the
// Simulator. Writes walk.json, plots of the ZMP, the COM and the per-step predictions against the measurements, and
// an HTML viewer of the motion.
//
// `cairn run`: the same walk planned on what the robot's head camera sees instead of the scenario's terrain -- the
// main diagram (planning/run: stereo -> occupancy and friction -> terrain -> the walk). It also writes terrain.png,
// the perceived terrain with the plan.

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "cairn/common/atomic_output_directory.h"
#include "cairn/common/json_writer.h"
#include "cairn/common/number_text.h"
#include "cairn/multibody/data.h"
#include "cairn/multibody/kinematics.h"
#include "cairn/multibody/plant/joint_pd_controller.h"
#include "cairn/multibody/urdf_parser.h"
#include "cairn/perception/friction/make_material_segmenter.h"
#include "cairn/planning/locomotion/walking_objective.h"
#include "cairn/planning/run/main_diagram.h"
#include "cairn/planning/run/scenario_stereo_scene.h"
#include "cairn/planning/scenarios/footstep_scenario.h"
#include "cairn/planning/walk/scenario_terrain_boxes.h"
#include "cairn/planning/walk/walk_diagram.h"
#include "cairn/planning/walk/walk_run.h"
#include "cairn/visualization/motion_html.h"
#include "choice_option.h"
#include "command_registry.h"
#include "data_directory.h"
#include "file_checks.h"
#include "numeric_option.h"
#include "oracle_cache.h"
#include "perception_report.h"
#include "plan_image.h"
#include "walk_plots.h"

namespace cairn::cli {
namespace {

using namespace cairn::planning;

constexpr double kMaxSettleTime = 10.0;  // s simulated after the reference ends
constexpr double kLogPeriod = 0.01;      // s between recorded samples
constexpr double kViewerPeriod = 0.04;   // s between the viewer's frames (25 per second)

struct WalkArguments {
  std::string scenario;
  std::string objective;
  std::string stabilizer = "fft";
  std::string out;
  OracleChoice oracle;
  double settle_time = 1.0;
  double step = 1e-3;
  bool open_loop = false;
  bool no_refine = false;
  bool json = false;
  // `cairn run`: plan on the head camera's view (the main diagram) with this material segmenter.
  bool perceive = false;
  std::string segmenter;
};

bool IsWalkOutput(const std::string& name) {
  return name == "walk.json" || name == "walk_zmp.png" || name == "walk_com.png" || name == "walk_steps.png" ||
         name == "walk.html" || name == "terrain.png" || name == "run.json" || name == "timing.json" ||
         name == "perception.png" || name == "run.html";
}

// The material of the scenario's ground under (x, y): the last region containing it (later regions lie on earlier
// ones), or "" where none does or the region states a friction instead.
std::string MaterialAt(const FootstepScenario& scenario, double x, double y) {
  std::string material;
  for (const FootstepScenario::Region& region : scenario.regions()) {
    if (region.Contains(Eigen::Vector2d(x, y))) material = region.material;
  }
  return material;
}

void MaybeNumber(JsonWriter& json, const char* key, double value, JsonWriter::NumberFormat format) {
  json.Key(key);
  if (std::isfinite(value)) {
    json.Number(value, format);
  } else {
    json.Null();
  }
}

// The walk's samples as the viewer's frames: 25 per second, fewer for a walk too long for the viewer's frame limit;
// the last sample (a fall) is always a frame.
void AddWalkFrames(const WalkRecord& record, visualization::MotionScene* scene) {
  if (record.samples.empty()) return;
  const auto every = std::max(static_cast<std::size_t>(std::lround(kViewerPeriod / kLogPeriod)),
                              record.samples.size() / (visualization::kMaxMotionFrames - 1) + 1);
  for (std::size_t k = 0; k < record.samples.size(); k += every) {
    scene->times.push_back(record.samples[k].time);
    scene->q.push_back(record.samples[k].q);
  }
  if ((record.samples.size() - 1) % every != 0) {
    scene->times.push_back(record.samples.back().time);
    scene->q.push_back(record.samples.back().q);
  }
}

// `perceived`: the terrain the main diagram planned on (`cairn run`), else null (`cairn walk`).
std::string WalkJson(const FootstepScenario& scenario, const std::string& objective, const std::string& stabilizer,
                     bool feedback, const multibody::Model& robot, const std::vector<std::string>& soles,
                     const WalkRecord& record, const std::vector<WalkStepComparison>& steps,
                     const TerrainMap* perceived) {
  const JsonWriter::NumberFormat f6 = JsonWriter::Fixed(6), f3 = JsonWriter::Fixed(3);
  JsonWriter json;
  json.BeginObject().Key("scenario").String(scenario.name()).Key("objective").String(objective);
  json.Key("stabilizer").String(stabilizer).Key("feedback").Bool(feedback).Key("walked").Bool(record.start.ready);
  json.Key("reason").String(record.start.reason);
  if (perceived != nullptr) {
    int ground = 0, walkable = 0;
    for (int row = 0; row < perceived->rows(); ++row) {
      for (int col = 0; col < perceived->cols(); ++col) {
        ground += perceived->has_ground(col, row) ? 1 : 0;
        walkable += perceived->walkable(col, row) ? 1 : 0;
      }
    }
    json.Key("perception").BeginObject().Key("cells").Integer(perceived->rows() * perceived->cols());
    json.Key("ground_cells").Integer(ground).Key("walkable_cells").Integer(walkable);
    json.Key("obstacle_voxels").Integer(perceived->occupied_voxels().size()).EndObject();
  }
  json.Key("plan").BeginObject().Key("found").Bool(record.plan.found).Key("steps").Integer(record.plan.steps.size());
  json.Key("duration").Number(record.plan.duration, f6).Key("energy_J").Number(record.plan.energy, f6);
  json.Key("max_rcof").Number(record.plan.max_rcof, f6).EndObject();
  json.Key("trajectory").BeginObject().Key("found").Bool(record.trajectory.found);
  json.Key("waypoints").Integer(record.trajectory.waypoints.size());
  json.Key("message").String(record.trajectory.report.message).EndObject();
  const StabilizationReport& r = record.reference.report;
  json.Key("stabilization").BeginObject().Key("success").Bool(r.success).Key("method").String(r.method);
  json.Key("samples").Integer(record.reference.q.size()).Key("period").Number(record.reference.period, f6);
  json.Key("rms_zmp_error_before").Number(r.rms_error_before, f6).Key("rms_zmp_error_after").Number(r.rms_error_after, f6);
  json.Key("max_zmp_error_after").Number(r.max_error_after, f6);
  json.Key("min_support_margin_after").Number(r.min_support_margin_after, f6).EndObject();
  double predicted_com = 0.0, predicted_heat = 0.0;
  for (const PlannedStep& step : record.plan.steps) {
    predicted_com += step.transition.com_work;
    predicted_heat += step.transition.heat;
  }
  if (record.start.ready) {
    const StanceGoal& goal = scenario.goal();
    const double distance = SoleDistance(robot, soles, record, goal.stance);
    json.Key("goal").BeginObject().Key("reached").Bool(!record.fell && distance <= goal.position_tolerance);
    json.Key("distance").Number(distance, f6).Key("tolerance").Number(goal.position_tolerance, f6);
    // The plan may end anywhere within the goal's tolerance: how far the soles ended from where it put them.
    const std::size_t steps = record.plan.steps.size();
    MaybeNumber(json, "last_stance_distance",
                steps > 0 ? SoleDistance(robot, soles, record, record.plan.StanceAfter(static_cast<int>(steps) - 1))
                          : std::nan(""),
                f6);
    json.EndObject();
    json.Key("fell").Bool(record.fell).Key("fall_reason").String(record.fall_reason);
    MaybeNumber(json, "fall_time", record.fell ? record.duration : std::nan(""), f3);
    json.Key("executed_duration").Number(record.duration, f3);
    json.Key("reference_duration").Number(record.reference.duration(), f6);
    const WalkSample& last = record.samples.back();
    json.Key("energy").BeginObject().Key("measured_com_J").Number(last.com_energy, f6);
    json.Key("measured_electrical_J").Number(last.electrical_energy, f6);
    json.Key("measured_heat_J").Number(last.heat, f6);
    json.Key("predicted_com_J").Number(predicted_com, f6).Key("predicted_heat_J").Number(predicted_heat, f6);
    json.Key("predicted_total_J").Number(predicted_com + predicted_heat, f6).EndObject();
    json.Key("slips").BeginArray();
    for (const multibody::SlipEvent& slip : record.slips) {
      json.BreakLine(2).BeginObject().Key("time").Number(slip.time, f3).Key("foot").String(slip.foot == 0 ? "left" : "right");
      json.Key("x").Number(slip.position.x(), f6).Key("y").Number(slip.position.y(), f6);
      json.Key("force_ratio").Number(slip.force_ratio, f6).EndObject();
    }
    json.EndArray();
  }
  json.Key("steps").BeginArray();
  for (const WalkStepComparison& s : steps) {
    json.BreakLine(2).BeginObject().Key("step").Integer(s.index).Key("foot").String(s.foot);
    const FootPose& pose = record.plan.steps[static_cast<std::size_t>(s.index - 1)].pose;
    json.Key("x").Number(pose.x, f6).Key("y").Number(pose.y, f6);
    json.Key("material").String(MaterialAt(scenario, pose.x, pose.y));
    json.Key("start").Number(s.start, f3).Key("end").Number(s.end, f3).Key("completed").Bool(s.completed);
    json.Key("mu_allowed").Number(s.mu_allowed, f6).Key("predicted_rcof").Number(s.predicted_rcof, f6);
    MaybeNumber(json, "measured_rcof", s.measured_rcof, f6);
    MaybeNumber(json, "measured_rcof_after_touchdown", s.measured_rcof_after_touchdown, f6);
    MaybeNumber(json, "measured_net_rcof", s.measured_net_rcof, f6);
    json.Key("predicted_com_J").Number(s.predicted_com_work, f6).Key("predicted_heat_J").Number(s.predicted_heat, f6);
    MaybeNumber(json, "measured_com_J", s.measured_com_energy, f6);
    MaybeNumber(json, "measured_electrical_J", s.measured_electrical_energy, f6);
    MaybeNumber(json, "measured_heat_J", s.measured_heat, f6);
    json.EndObject();
  }
  json.EndArray().EndObject();
  return json.text();
}

int Run(const WalkArguments& args) {
  CheckInputFile("--scenario", args.scenario, "a scenario YAML file");
  const FootstepScenario scenario = FootstepScenario::Load(args.scenario);
  OracleChoice oracle_choice = args.oracle;
  oracle_choice.Resolve(scenario);
  // Before the oracle is loaded (or built): a scenario the camera cannot see fails now.
  if (args.perceive) ScenarioStereoScene(scenario);
  const std::string objective_name = args.objective.empty() ? scenario.objective() : args.objective;
  const WalkingObjective objective = ParseWalkingObjective(objective_name);
  // Before the oracle is loaded (or built): a scenario the plant cannot stand on fails now.
  ScenarioTerrainBoxes(scenario);
  std::optional<AtomicOutputDirectory> out;
  if (!args.out.empty()) out.emplace(args.out, IsWalkOutput);

  const std::string walking = scenario.robot().empty() ? DataDirectory() + "/robots/cairn_humanoid_walking.yaml"
                                                       : scenario.robot();
  CheckInputFile("the scenario's robot", walking, "a walking-model YAML file");
  const std::string urdf_path = DataDirectory() + "/robots/cairn_humanoid.urdf";
  const std::string control = DataDirectory() + "/robots/cairn_humanoid_control.yaml";
  const auto walking_model = std::make_shared<const WalkingModel>(WalkingModel::Load(walking));
  const auto oracle =
      std::make_shared<const TransitionOracle>(LoadChosenOracle(oracle_choice, walking_model, objective));
  multibody::UrdfOptions urdf;
  urdf.floating_base = true;
  const auto robot = std::make_shared<const multibody::Model>(multibody::ParseUrdfFile(urdf_path, urdf));
  const auto controller =
      std::make_shared<const multibody::JointPdController>(multibody::JointPdController::Load(*robot, control));

  WalkSetup setup = WalkSetupFromScenario(scenario, oracle, walking_model, objective, robot, controller);
  setup.stabilizer.method = args.stabilizer;
  setup.feedback = !args.open_loop;
  // The refinement optimises the analytic model's cost: steps priced by the plant keep the plant's timings.
  if (args.no_refine || oracle_choice.measured()) setup.refine_model = nullptr;
  setup.plant.bullet.time_step = args.step;
  setup.plant.stop_on_fall = true;
  WalkRunOptions run;
  run.log_period = kLogPeriod;
  run.settle_time = args.settle_time;
  WalkRecord record;
  std::shared_ptr<const TerrainMap> perceived;
  double perception_seconds = 0.0;
  MainRecord main;  // `cairn run`: what the first frame's perception made (the walk is moved into `record`)
  std::optional<PerceptionSetup> perception;
  if (args.perceive) {
    const SyntheticCamera camera;
    perception = PerceptionSetupFromScenario(scenario, camera.Calibration(),
                                             perception::MakeMaterialSegmenter(args.segmenter));
    main = RunMainDiagram(BuildMainDiagram(setup, *perception, ScenarioCamera(scenario, camera, perception->period)),
                          run);
    record = std::move(main.walk);
    perceived = main.terrain;
    perception_seconds = main.perception_seconds;
  } else {
    record = RunWalk(BuildWalkDiagram(setup), run);
  }
  const std::vector<WalkStepComparison> steps = CompareWalkSteps(record);
  const std::string json =
      WalkJson(scenario, objective_name, args.stabilizer, setup.feedback, *robot, setup.plant.sole_bodies, record,
               steps, perceived.get());

  // The wall times per stage: printed with --json and written to timing.json, never into walk.json or run.json,
  // so that runs of the same inputs write the same bytes there.
  JsonWriter timing;
  timing.BeginObject().Key("perception_s").Number(perception_seconds, JsonWriter::Fixed(3));
  timing.Key("footsteps_s").Number(record.start.seconds.footsteps, JsonWriter::Fixed(3));
  timing.Key("trajectory_s").Number(record.start.seconds.trajectory, JsonWriter::Fixed(3));
  timing.Key("stabilizer_s").Number(record.start.seconds.stabilizer, JsonWriter::Fixed(3));
  timing.Key("plant_s").Number(record.plant_seconds, JsonWriter::Fixed(3)).EndObject();
  if (out) {
    out->WriteFile(args.perceive ? "run.json" : "walk.json", json + "\n");
    if (args.perceive) out->WriteFile("timing.json", timing.text() + "\n");
    if (perceived != nullptr) {
      out->WriteFile("terrain.png", PlanImagePng(*perceived, record.plan, scenario.goal(), setup.geometry,
                                                      "the perceived terrain and the plan, from above"));
      out->WriteFile("perception.png", PerceptionReportPng(main, perception->registry, perception->eta));
    }
    if (record.start.ready) {
      out->WriteFile("walk_zmp.png", WalkZmpPng(record, setup.geometry));
      out->WriteFile("walk_com.png", WalkComPng(record));
      out->WriteFile("walk_steps.png", WalkStepsPng(steps));
      visualization::MotionScene scene;
      scene.title = "cairn walk: " + scenario.name() + " (" + args.stabilizer + ")";
      for (const multibody::TerrainBox& box : setup.plant_terrain) {
        scene.boxes.push_back({box.name, box.X_WB, box.size, box.friction});
      }
      AddWalkFrames(record, &scene);
      out->WriteFile("walk.html", visualization::MotionHtml(*robot, scene));
    }
    if (perceived != nullptr) {
      // What the robot saw: the perceived terrain and occupied cells, with the walk, or the robot at its start.
      visualization::MotionScene scene;
      scene.title = "cairn run: " + scenario.name() + ", the terrain as perceived";
      scene.boxes = PerceivedTerrainBoxes(*perceived);
      if (record.start.ready) {
        AddWalkFrames(record, &scene);
      } else {
        scene.times.push_back(0.0);
        scene.q.push_back(StandingAtStart(*robot, setup.plant.sole_bodies, scenario.start()));
      }
      out->WriteFile("run.html", visualization::MotionHtml(*robot, scene));
    }
    out->Commit();
  }
  if (args.json) {
    std::string line = json;
    line.pop_back();
    std::printf("%s, \"seconds\": %s}\n", line.c_str(), timing.text().c_str());
    return 0;
  }
  std::printf("%s       %s (objective %s, stabiliser %s%s)\n", args.perceive ? "run " : "walk",
              scenario.name().c_str(), objective_name.c_str(), args.stabilizer.c_str(),
              args.open_loop ? ", open loop" : "");
  if (perceived != nullptr) {
    std::map<std::string, int> footholds;  // per material of the true ground
    std::printf("perceived  terrain of %d x %d cells from the head camera's first frame\n", perceived->cols(),
                perceived->rows());
    for (const WalkStepComparison& s : steps) {
      const FootPose& pose = record.plan.steps[static_cast<std::size_t>(s.index - 1)].pose;
      const std::string material = MaterialAt(scenario, pose.x, pose.y);
      std::printf("  step %2d  %-5s foot to (%6.3f, %6.3f) on %-8s mu allowed %.3f, predicted RCOF %.3f\n", s.index,
                  s.foot.c_str(), pose.x, pose.y, material.empty() ? "-" : material.c_str(), s.mu_allowed,
                  s.predicted_rcof);
      ++footholds[material.empty() ? "-" : material];
    }
    std::string counts;
    for (const auto& [material, count] : footholds) counts += " " + material + " " + std::to_string(count);
    std::printf("footholds %s\n", counts.c_str());
  }
  std::printf("plan       %s: %zu steps, %.3f s, %.1f J predicted\n", record.plan.found ? "found" : "NOT FOUND",
              record.plan.steps.size(), record.plan.duration, record.plan.energy);
  if (!record.start.ready) {
    std::printf("not walked %s\n", record.start.reason.c_str());
  } else {
    const WalkSample& last = record.samples.back();
    std::printf("reference  %zu samples at %.4g s; ZMP RMS error %.4f -> %.4f m\n", record.reference.q.size(),
                record.reference.period, record.reference.report.rms_error_before,
                record.reference.report.rms_error_after);
    const std::size_t steps = record.plan.steps.size();
    std::printf("walked     %.3f s of %.3f s; goal distance %.3f m (tolerance %.3f m), %.3f m from the plan's end\n",
                record.duration, record.reference.duration() + args.settle_time,
                SoleDistance(*robot, setup.plant.sole_bodies, record, scenario.goal().stance),
                scenario.goal().position_tolerance,
                steps > 0 ? SoleDistance(*robot, setup.plant.sole_bodies, record,
                                         record.plan.StanceAfter(static_cast<int>(steps) - 1))
                          : std::nan(""));
    std::printf("fall       %s\n", record.fell ? record.fall_reason.c_str() : "none");
    std::printf("slips      %zu\n", record.slips.size());
    std::printf("energy     E_COM %.2f J, E_ele %.2f J (Joule heat %.2f J) measured\n", last.com_energy,
                last.electrical_energy, last.heat);
    if (args.perceive) std::printf("time       perception %.2f s (the first frame)\n", perception_seconds);
    std::printf("time       footsteps %.2f s, trajectory %.2f s, stabiliser %.2f s, plant %.2f s\n",
                record.start.seconds.footsteps, record.start.seconds.trajectory, record.start.seconds.stabilizer,
                record.plant_seconds);
  }
  if (out) {
    std::printf("wrote      %s/%s%s%s\n", args.out.c_str(),
                args.perceive ? "run.json, timing.json" : "walk.json",
                perceived ? ", perception.png, terrain.png, run.html" : "",
                record.start.ready ? ", walk_zmp.png, walk_com.png, walk_steps.png, walk.html" : "");
  }
  return 0;
}

}  // namespace

void RegisterWalkCommand(CommandRegistry* registry) {
  registry->Add("walk", "Plan a scenario's walk, stabilise it and walk it in the Bullet plant (one diagram)",
                [](CLI::App& app) -> CommandAction {
                  auto args = std::make_shared<WalkArguments>();
                  app.add_option("--scenario", args->scenario, "Scenario YAML (docs/scenarios.md; box regions)")
                      ->required();
                  AddChoiceOption(app, "--objective", &args->objective, "Step objective (default: the scenario's)",
                                  WalkingObjectiveNames());
                  AddChoiceOption(app, "--stabilizer", &args->stabilizer, "ZMP stabilisation of the reference",
                                  {"fft", "preview", "none"});
                  AddNumberOption(app, "--settle-time", &args->settle_time,
                                  "Simulated time after the reference ends [s]",
                                  NumberRange::Closed(0.0, kMaxSettleTime));
                  AddNumberOption(app, "--step", &args->step, "Plant time step [s]",
                                  NumberRange::AboveAtMost(0.0, multibody::BulletPlantOptions::kMaxTimeStep));
                  app.add_option("--out", args->out,
                                 "Folder for walk.json, walk_zmp.png, walk_com.png, walk_steps.png, walk.html "
                                 "(replaced as a whole)");
                  AddOracleOptions(app, &args->oracle);
                  app.add_flag("--open-loop", args->open_loop,
                               "Play the stabilised reference without the capture-point feedback (BalanceFeedback)");
                  app.add_flag("--no-refine", args->no_refine,
                               "Keep the oracle table's step parameters (skip the SLSQP refinement of each step)");
                  app.add_flag("--json", args->json, "Print walk.json and the stages' wall times as one JSON object");
                  return [args] { return Run(*args); };
                });
  registry->Add(
      "run", "The main diagram: see the scenario through the head camera, plan on what was seen, walk it in the plant",
      [](CLI::App& app) -> CommandAction {
        auto args = std::make_shared<WalkArguments>();
        args->perceive = true;
        args->segmenter = "builtin:" + DataDirectory() + "/models/builtin_material_segmenter.yaml";
        app.add_option("--scenario", args->scenario,
                       "Scenario YAML whose regions name materials (docs/main_diagram.md; e.g. "
                       "examples/scenarios/mockup/mockup.yaml)")
            ->required();
        AddChoiceOption(app, "--objective", &args->objective, "Step objective (default: the scenario's)",
                        WalkingObjectiveNames());
        AddChoiceOption(app, "--stabilizer", &args->stabilizer, "ZMP stabilisation of the reference",
                        {"fft", "preview", "none"});
        AddNumberOption(app, "--settle-time", &args->settle_time, "Simulated time after the reference ends [s]",
                        NumberRange::Closed(0.0, kMaxSettleTime));
        app.add_option("--segmenter", args->segmenter,
                       "Material segmenter: builtin:PATH or onnx:PATH (default: the built-in one in data/models)");
        app.add_option("--out", args->out,
                       "Folder for run.json, timing.json, perception.png, terrain.png, run.html and, when walked, "
                       "walk_zmp.png, walk_com.png, walk_steps.png, walk.html (replaced as a whole)");
        AddOracleOptions(app, &args->oracle);
        app.add_flag("--json", args->json, "Print run.json and the stages' wall times as one JSON object");
        return [args] { return Run(*args); };
      });
}

}  // namespace cairn::cli
