// `cairn simulate`: the humanoid standing (or dropped, or following a joint trajectory file) in the Bullet plant
// under joint PD control, on flat ground or a scenario's terrain boxes; prints a summary and writes a log (CSV), a summary (JSON) and a plot (PNG) of the
// contact forces and the base height.

#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "cairn/common/atomic_output_directory.h"
#include "cairn/common/json_writer.h"
#include "cairn/common/number_text.h"
#include "cairn/multibody/configuration.h"
#include "cairn/multibody/data.h"
#include "cairn/multibody/kinematics.h"
#include "cairn/multibody/plant/humanoid_plant.h"
#include "cairn/multibody/plant/joint_drive.h"
#include "cairn/multibody/plant/joint_pd_controller.h"
#include "cairn/multibody/plant/joint_trajectory.h"
#include "cairn/multibody/plant/plant_scenario.h"
#include "cairn/multibody/urdf_parser.h"
#include "cairn/systems/analysis/simulator.h"
#include "cairn/systems/framework/diagram_builder.h"
#include "cairn/systems/primitives/constant_vector_source.h"
#include "cairn/systems/primitives/function_system.h"
#include "command_registry.h"
#include "data_directory.h"
#include "file_checks.h"
#include "numeric_option.h"
#include "usage_error.h"

namespace cairn::cli {
namespace {

using namespace cairn::multibody;

constexpr double kMaxDuration = 60.0;   // s: 60000 plant steps at 1 ms, about 15 s of wall time
constexpr double kLogPeriod = 0.01;     // s between log rows
constexpr double kMaxFriction = 10.0;   // Bullet's cap on the combined coefficient

struct SimulateArguments {
  std::string robot = DataDirectory() + "/robots/cairn_humanoid.urdf";
  std::string control = DataDirectory() + "/robots/cairn_humanoid_control.yaml";
  std::string walking = DataDirectory() + "/robots/cairn_humanoid_walking.yaml";
  std::string scenario;
  std::string trajectory;
  std::string out;
  double duration = 2.0;
  double step = 1e-3;
  double friction = 0.8;
  double drop = 0.0;
  bool json = false;
};

// The files `--out` holds; the folder is replaced as a whole.
bool IsSimulateOutput(const std::string& name) {
  return name == "log.csv" || name == "summary.json" || name == "plot.png";
}

struct LogRow {
  double time;
  Eigen::VectorXd base;  // x y z qw qx qy qz
  double left_fn, left_ft, right_fn, right_ft;
  Eigen::Vector3d zmp;
  double com_energy, electrical_energy;
};

// Two stacked panels: the soles' normal forces, and the base height, against time.
std::string PlotPng(const std::vector<LogRow>& rows, double duration) {
  const int width = 900, panel = 300, margin = 60;
  cv::Mat image(2 * panel + 2 * margin, width, CV_8UC3, cv::Scalar(255, 255, 255));
  auto draw_panel = [&](int top, const std::string& title, const std::vector<std::pair<std::vector<double>, cv::Scalar>>& series) {
    double lo = 0.0, hi = 1e-9;
    bool first = true;
    for (const auto& [values, colour] : series) {
      for (double v : values) {
        if (!std::isfinite(v)) continue;
        if (first) lo = hi = v;
        first = false;
        lo = std::min(lo, v);
        hi = std::max(hi, v);
      }
    }
    if (hi - lo < 1e-9) hi = lo + 1.0;
    const double pad = 0.05 * (hi - lo);
    lo -= pad;
    hi += pad;
    const int left = margin, right = width - 20, bottom = top + panel - 30;
    cv::rectangle(image, cv::Point(left, top), cv::Point(right, bottom), cv::Scalar(0, 0, 0), 1);
    cv::putText(image, title, cv::Point(left, top - 8), cv::FONT_HERSHEY_SIMPLEX, 0.5, cv::Scalar(0, 0, 0), 1, cv::LINE_AA);
    for (int k = 0; k <= 4; ++k) {
      const double value = lo + (hi - lo) * k / 4.0;
      const int y = bottom - static_cast<int>(std::lround((bottom - top) * k / 4.0));
      cv::line(image, cv::Point(left, y), cv::Point(right, y), cv::Scalar(225, 225, 225), 1);
      cv::putText(image, FormatShort(value), cv::Point(2, y + 4), cv::FONT_HERSHEY_SIMPLEX, 0.35, cv::Scalar(0, 0, 0), 1,
                  cv::LINE_AA);
      const double t = duration * k / 4.0;
      const int x = left + static_cast<int>(std::lround((right - left) * k / 4.0));
      cv::putText(image, FormatShort(t) + " s", cv::Point(x - 10, bottom + 16), cv::FONT_HERSHEY_SIMPLEX, 0.35,
                  cv::Scalar(0, 0, 0), 1, cv::LINE_AA);
    }
    for (const auto& [values, colour] : series) {
      std::vector<cv::Point> points;
      for (std::size_t i = 0; i < values.size(); ++i) {
        if (!std::isfinite(values[i])) continue;
        const double x = left + (right - left) * rows[i].time / duration;
        const double y = bottom - (bottom - top) * (values[i] - lo) / (hi - lo);
        points.emplace_back(static_cast<int>(std::lround(x)), static_cast<int>(std::lround(y)));
      }
      if (points.size() >= 2) cv::polylines(image, points, false, colour, 1, cv::LINE_AA);
    }
  };
  std::vector<double> left, right, height;
  for (const LogRow& row : rows) {
    left.push_back(row.left_fn);
    right.push_back(row.right_fn);
    height.push_back(row.base[2]);
  }
  draw_panel(margin, "sole normal force [N]: left (blue), right (red)",
             {{left, cv::Scalar(200, 80, 0)}, {right, cv::Scalar(0, 0, 200)}});
  draw_panel(margin + panel + margin / 2, "base height [m]", {{height, cv::Scalar(0, 120, 0)}});
  std::vector<uchar> png;
  if (!cv::imencode(".png", image, png)) throw std::runtime_error("cannot encode the plot as PNG");
  return std::string(png.begin(), png.end());
}

int Run(const SimulateArguments& args) {
  CheckInputFile("--robot", args.robot, "a URDF file");
  CheckInputFile("--control", args.control, "a control YAML file");
  CheckInputFile("--walking", args.walking, "a walking-model YAML file");
  if (!args.scenario.empty()) CheckInputFile("--scenario", args.scenario, "a plant scenario YAML file");
  if (!args.trajectory.empty()) CheckInputFile("--trajectory", args.trajectory, "a joint trajectory CSV file");
  std::optional<AtomicOutputDirectory> out;
  if (!args.out.empty()) out.emplace(args.out, IsSimulateOutput);

  UrdfOptions urdf;
  urdf.floating_base = true;
  const Model model = ParseUrdfFile(args.robot, urdf);
  const JointPdController pd = JointPdController::Load(model, args.control);
  HumanoidPlantOptions options;
  options.bullet.time_step = args.step;
  options.drives = LoadJointDrives(model, args.walking);
  options.stop_on_fall = true;
  std::vector<TerrainBox> terrain;
  double drop = args.drop;
  if (!args.scenario.empty()) {
    const PlantScenario scenario = PlantScenario::Load(args.scenario);
    terrain = scenario.terrain;
    drop += scenario.drop_height;
  } else {
    TerrainBox ground;
    ground.name = "ground";
    ground.X_WB = Pose(Eigen::Matrix3d::Identity(), Eigen::Vector3d(0.0, 0.0, -0.5));
    ground.size = Eigen::Vector3d(40.0, 40.0, 1.0);
    ground.friction = args.friction;
    terrain.push_back(ground);
  }
  // Standing: joints at zero, the lower sole `drop` above z = 0.
  Eigen::VectorXd q0 = NeutralConfiguration(model);
  {
    Data data(model);
    ForwardKinematics(model, data, q0);
    double lowest = std::numeric_limits<double>::infinity();
    for (const std::string& sole : options.sole_bodies) {
      lowest = std::min(lowest, data.X_world[static_cast<std::size_t>(model.GetBodyIndex(sole))].translation().z());
    }
    q0[2] = -lowest + drop;
  }

  systems::DiagramBuilder builder;
  auto* plant = builder.AddNamedSystem<HumanoidPlant>("plant", model, terrain, pd, q0, options);
  if (args.trajectory.empty()) {
    Eigen::VectorXd reference = Eigen::VectorXd::Zero(model.nq() + model.nv());
    reference.head(model.nq()) = q0;
    auto* source = builder.AddNamedSystem<systems::ConstantVectorSource>("reference", reference);
    builder.Connect(source->get_output_port(0), plant->GetInputPort("reference"));
  } else {
    // The file's joints follow the trajectory; the others hold the standing posture.
    const auto trajectory = std::make_shared<const JointTrajectory>(JointTrajectory::LoadCsv(model, args.trajectory));
    const int nq = model.nq(), nv = model.nv();
    auto* source = builder.AddNamedSystem<systems::FunctionSystem>(
        "reference", 0, nq + nv, [trajectory, q0, nq, nv](double t, const Eigen::VectorXd&) {
          Eigen::VectorXd q, v;
          trajectory->Evaluate(t, q0, &q, &v);
          Eigen::VectorXd reference(nq + nv);
          reference << q, v;
          return reference;
        });
    builder.Connect(source->get_output_port(0), plant->GetInputPort("reference"));
  }
  auto diagram = builder.Build();
  systems::Simulator simulator(*diagram);

  std::vector<LogRow> rows;
  systems::SimulatorStatus status;
  const long long samples = std::llround(args.duration / kLogPeriod);
  auto record = [&]() {
    const systems::Context& context = diagram->GetSubsystemContext(*plant, simulator.get_context());
    const Eigen::VectorXd& x = plant->GetOutputPort("state").Eval<Eigen::VectorXd>(context);
    const auto& soles = plant->GetOutputPort("contacts").Eval<std::vector<SoleState>>(context);
    const Eigen::VectorXd& energy = plant->GetOutputPort("energy").Eval<Eigen::VectorXd>(context);
    rows.push_back(LogRow{context.get_time(), x.head(7), soles[0].normal_force, soles[0].tangential_force,
                          soles[1].normal_force, soles[1].tangential_force,
                          plant->GetOutputPort("zmp").Eval<Eigen::VectorXd>(context), energy[0], energy[1]});
  };
  simulator.Initialize();
  record();
  for (long long k = 1; k <= samples; ++k) {
    status = simulator.AdvanceTo(std::min(args.duration, static_cast<double>(k) * kLogPeriod));
    record();
    if (!status.reached_boundary_time()) break;
  }
  if (status.reason == systems::SimulatorStatus::Reason::kEventHandlerFailed) {
    throw std::runtime_error("the simulation failed at t = " + FormatShort(status.time) + " s: " + status.message);
  }
  const systems::Context& context = diagram->GetSubsystemContext(*plant, simulator.get_context());
  const auto& slips = plant->GetOutputPort("slips").Eval<std::vector<SlipEvent>>(context);
  const auto& stances = plant->GetOutputPort("stances").Eval<std::vector<StancePhase>>(context);
  const bool fell = !status.reached_boundary_time();

  std::string csv = "time,base_x,base_y,base_z,base_qw,base_qx,base_qy,base_qz,left_fn,left_ft,right_fn,right_ft,"
                    "zmp_x,zmp_y,e_com,e_ele\n";
  for (const LogRow& row : rows) {
    char line[512];
    std::snprintf(line, sizeof(line), "%.3f,%.6f,%.6f,%.6f,%.6f,%.6f,%.6f,%.6f,%.3f,%.3f,%.3f,%.3f,%.5f,%.5f,%.4f,%.4f\n",
                  row.time, row.base[0], row.base[1], row.base[2], row.base[3], row.base[4], row.base[5], row.base[6],
                  row.left_fn, row.left_ft, row.right_fn, row.right_ft, row.zmp.x(), row.zmp.y(), row.com_energy,
                  row.electrical_energy);
    csv += line;
  }
  JsonWriter json;
  const JsonWriter::NumberFormat f6 = JsonWriter::Fixed(6);
  json.BeginObject().Key("robot").String(model.name()).Key("duration").Number(rows.back().time, f6);
  json.Key("time_step").Number(args.step, JsonWriter::Fixed(6)).Key("fell").Bool(fell);
  json.Key("fall_reason").String(fell ? status.message : "");
  json.Key("com_energy_J").Number(rows.back().com_energy, f6);
  json.Key("electrical_energy_J").Number(rows.back().electrical_energy, f6);
  json.Key("base_final").BeginArray();
  for (int i = 0; i < 7; ++i) json.Number(rows.back().base[i], f6);
  json.EndArray().Key("slips").BeginArray();
  for (const SlipEvent& slip : slips) {
    json.BeginObject().Key("time").Number(slip.time, JsonWriter::Fixed(3)).Key("foot").String(slip.foot == 0 ? "left" : "right");
    json.Key("x").Number(slip.position.x(), f6).Key("y").Number(slip.position.y(), f6);
    json.Key("force_ratio").Number(slip.force_ratio, f6).EndObject();
  }
  json.EndArray().Key("stances").BeginArray();
  for (const StancePhase& stance : stances) {
    json.BeginObject().Key("foot").String(stance.foot == 0 ? "left" : "right");
    json.Key("start").Number(stance.start, JsonWriter::Fixed(3)).Key("end").Number(stance.end, JsonWriter::Fixed(3));
    json.Key("rcof").Number(stance.rcof, f6).Key("rcof_after_touchdown").Number(stance.rcof_after_touchdown, f6);
    json.Key("net_rcof").Number(stance.net_rcof, f6).Key("finished").Bool(stance.finished).EndObject();
  }
  json.EndArray().EndObject();

  if (out) {
    out->WriteFile("log.csv", csv);
    out->WriteFile("summary.json", json.text() + "\n");
    out->WriteFile("plot.png", PlotPng(rows, std::max(rows.back().time, kLogPeriod)));
    out->Commit();
  }
  if (args.json) {
    std::printf("%s\n", json.text().c_str());
    return 0;
  }
  const LogRow& last = rows.back();
  std::printf("simulate   %s, %zu terrain box(es), %.3f s at %.4g s steps\n", model.name().c_str(), terrain.size(),
              last.time, args.step);
  std::printf("base       (%.4f, %.4f, %.4f) m at the end; start height %.4f m\n", last.base[0], last.base[1],
              last.base[2], q0[2]);
  std::printf("contacts   left %.1f N, right %.1f N; ZMP (%.4f, %.4f) m\n", last.left_fn, last.right_fn, last.zmp.x(),
              last.zmp.y());
  std::printf("energy     E_COM %.3f J, E_ele %.3f J\n", last.com_energy, last.electrical_energy);
  std::printf("slips      %zu%s\n", slips.size(),
              slips.empty() ? "" : (" (first at " + FormatShort(slips.front().time) + " s)").c_str());
  std::printf("fall       %s\n", fell ? status.message.c_str() : "none");
  if (out) std::printf("wrote      %s/log.csv, %s/summary.json, %s/plot.png\n", args.out.c_str(), args.out.c_str(),
                       args.out.c_str());
  return 0;
}

}  // namespace

void RegisterSimulateCommand(CommandRegistry* registry) {
  registry->Add("simulate", "Simulate the humanoid in the Bullet plant under joint PD control (standing or a trajectory)",
                [](CLI::App& app) -> CommandAction {
                  auto args = std::make_shared<SimulateArguments>();
                  app.add_option("--robot", args->robot, "Robot URDF (floating base)")->capture_default_str();
                  app.add_option("--control", args->control, "PD gains YAML")->capture_default_str();
                  app.add_option("--walking", args->walking, "Walking-model YAML (drive constants of E_ele)")
                      ->capture_default_str();
                  app.add_option("--scenario", args->scenario,
                                 "Plant scenario YAML (terrain boxes with friction; docs/simulate.md)");
                  app.add_option("--trajectory", args->trajectory,
                                 "Joint trajectory CSV (time,<joint>,...; docs/simulate.md) instead of standing still");
                  AddNumberOption(app, "--duration", &args->duration, "Simulated time [s]",
                                  NumberRange::AboveAtMost(0.0, kMaxDuration));
                  AddNumberOption(app, "--step", &args->step, "Plant time step [s]",
                                  NumberRange::AboveAtMost(0.0, BulletPlantOptions::kMaxTimeStep));
                  AddNumberOption(app, "--friction", &args->friction, "Ground friction without --scenario",
                                  NumberRange::Closed(0.0, kMaxFriction));
                  AddNumberOption(app, "--drop", &args->drop, "Start the soles this high above the ground [m]",
                                  NumberRange::Closed(0.0, 2.0));
                  app.add_option("--out", args->out, "Write log.csv, summary.json and plot.png into this folder");
                  app.add_flag("--json", args->json, "Print the summary as one JSON object");
                  return [args]() {
                    if (args->duration / args->step > 1e6) {
                      throw UsageError("--duration " + FormatShort(args->duration) + " s at --step " +
                                       FormatShort(args->step) + " s takes " +
                                       FormatShort(args->duration / args->step) +
                                       " plant steps, more than the limit of 1e+06; shorten --duration or "
                                       "lengthen --step");
                    }
                    return Run(*args);
                  };
                });
}

}  // namespace cairn::cli
