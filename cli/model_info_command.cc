// `cairn model-info <urdf>`: loads a URDF into a multibody Model and summarises it (bodies, joints, nq/nv,
// total mass, centre of mass at the zero configuration, frames), as text or JSON.

#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include <cairn/common/json_writer.h>
#include <cairn/multibody/center_of_mass.h>
#include <cairn/multibody/configuration.h>
#include <cairn/multibody/data.h>
#include <cairn/multibody/urdf_parser.h>

#include "command_registry.h"
#include "file_checks.h"

namespace cairn::cli {
namespace {

using multibody::JointType;

struct ModelInfoOptions {
  std::string urdf;
  std::vector<std::string> packages;
  bool floating_base = false;
  bool json = false;
};

// The document as a person reads it: one line per body and per joint. Nine significant digits; JSON has no
// infinity, so unlimited joints report null.
std::string ModelJson(const multibody::Model& model, const std::string& file, bool has_mass,
                      const Eigen::Vector3d& com) {
  const JsonWriter::NumberFormat digits = JsonWriter::Significant(9);
  JsonWriter json;
  json.BeginObject().Key("name").String(model.name()).Key("file").String(file);
  json.Key("nq").Integer(model.nq()).Key("nv").Integer(model.nv());
  json.Key("total_mass").Number(model.total_mass(), digits).Key("com_at_zero");
  if (has_mass) {
    json.BeginArray().Number(com.x(), digits).Number(com.y(), digits).Number(com.z(), digits).EndArray();
  } else {
    json.Null();
  }
  json.BreakLine(1).Key("bodies").BeginArray();
  for (int b = 0; b < model.num_bodies(); ++b) {
    const multibody::Body& body = model.body(b);
    json.BreakLine(3).BeginObject().Key("name").String(body.name).Key("mass").Number(body.inertia.mass(), digits);
    json.Key("parent");
    if (b > 0) {
      json.String(model.body(model.parent(b)).name);
    } else {
      json.Null();
    }
    json.Key("collisions").Integer(body.collisions.size()).Key("visuals").Integer(body.visuals.size()).EndObject();
  }
  json.EndArray().BreakLine(1).Key("joints").BeginArray();
  for (int j = 1; j < model.num_bodies(); ++j) {
    const multibody::Joint& joint = model.joint(j);
    json.BreakLine(3).BeginObject().Key("name").String(joint.name);
    json.Key("type").String(joint.continuous ? "continuous" : multibody::JointTypeName(joint.type));
    json.Key("parent").String(model.body(joint.parent).name).Key("child").String(model.body(j).name);
    json.Key("idx_q").Integer(joint.idx_q).Key("idx_v").Integer(joint.idx_v);
    json.Key("lower").Number(joint.lower_limit, digits).Key("upper").Number(joint.upper_limit, digits);
    json.Key("velocity").Number(joint.velocity_limit, digits).Key("effort").Number(joint.effort_limit, digits);
    json.EndObject();
  }
  json.EndArray().BreakLine(1).Key("frames").BeginArray();
  for (int f = 0; f < model.num_frames(); ++f) {
    json.BeginObject().Key("name").String(model.frame(f).name);
    json.Key("body").String(model.body(model.frame(f).body).name).EndObject();
  }
  json.EndArray().EndObject();
  return json.text();
}

std::string Vector(const Eigen::Vector3d& v) {
  char buffer[96];
  std::snprintf(buffer, sizeof(buffer), "(%.4f, %.4f, %.4f)", v.x(), v.y(), v.z());
  return buffer;
}

int Run(const ModelInfoOptions& options) {
  CheckInputFile("the URDF", options.urdf, "a URDF file");
  multibody::UrdfOptions urdf_options;
  urdf_options.floating_base = options.floating_base;
  for (const std::string& spec : options.packages) urdf_options.packages.AddSpec(spec);
  const multibody::Model model = multibody::ParseUrdfFile(options.urdf, urdf_options);
  multibody::Data data(model);
  const Eigen::VectorXd q0 = multibody::NeutralConfiguration(model);
  Eigen::Vector3d com = Eigen::Vector3d::Zero();
  const bool has_mass = model.total_mass() > 0.0;
  if (has_mass) com = multibody::CenterOfMass(model, data, q0);
  int moving = 0;
  for (int j = 1; j < model.num_bodies(); ++j) moving += model.joint(j).nv > 0 ? 1 : 0;

  std::ostringstream out;
  if (options.json) {
    std::cout << ModelJson(model, options.urdf, has_mass, com) << "\n";
    return 0;
  }
  char line[512];
  std::snprintf(line, sizeof(line), "Model '%s' from %s\n", model.name().c_str(), options.urdf.c_str());
  out << line;
  std::snprintf(line, sizeof(line),
                "  nq = %d, nv = %d; %d bodies besides the world, %d moving joints, %d fixed; %s base\n", model.nq(),
                model.nv(), model.num_bodies() - 1, moving, model.num_bodies() - 1 - moving,
                options.floating_base ? "floating (quaternion)" : "fixed");
  out << line;
  std::snprintf(line, sizeof(line), "  total mass: %.6g kg\n", model.total_mass());
  out << line;
  out << "  centre of mass at the zero configuration: "
      << (has_mass ? Vector(com) + " m" : std::string("none (massless model)")) << "\n";
  out << "Bodies (name, mass [kg], parent, collision/visual shapes):\n";
  for (int b = 1; b < model.num_bodies(); ++b) {
    const multibody::Body& body = model.body(b);
    std::snprintf(line, sizeof(line), "  %-40s %9.4f  %-32s %zu/%zu\n", body.name.c_str(), body.inertia.mass(),
                  model.body(model.parent(b)).name.c_str(), body.collisions.size(), body.visuals.size());
    out << line;
  }
  out << "Joints (name, type, q/v index, limits [lower, upper] / velocity / effort):\n";
  for (int j = 1; j < model.num_bodies(); ++j) {
    const multibody::Joint& joint = model.joint(j);
    std::string limits;
    if (joint.type == JointType::kRevolute || joint.type == JointType::kPrismatic) {
      char buffer[160];
      std::snprintf(buffer, sizeof(buffer), "[%.4g, %.4g] / %.4g / %.4g", joint.lower_limit, joint.upper_limit,
                    joint.velocity_limit, joint.effort_limit);
      limits = buffer;
    }
    std::snprintf(line, sizeof(line), "  %-40s %-10s %3d/%-3d %s\n", joint.name.c_str(),
                  joint.continuous ? "continuous" : multibody::JointTypeName(joint.type), joint.idx_q, joint.idx_v,
                  limits.c_str());
    out << line;
  }
  out << "Frames (" << model.num_frames() << "):";
  for (int f = 0; f < model.num_frames(); ++f) out << (f % 6 == 0 ? "\n  " : " ") << model.frame(f).name;
  out << "\n";
  std::cout << out.str();
  return 0;
}

}  // namespace

void RegisterModelInfoCommand(CommandRegistry* registry) {
  registry->Add("model-info", "Load a URDF and summarise its bodies, joints, mass and frames",
                [](CLI::App& app) -> CommandAction {
                  auto options = std::make_shared<ModelInfoOptions>();
                  app.add_option("urdf", options->urdf, "URDF file")->required();
                  app.add_option("--package", options->packages,
                                 "Map a package:// name to a folder, as name=path (repeatable)")
                      ->expected(1)
                      ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
                  app.add_flag("--floating-base", options->floating_base,
                               "Attach the root link with a quaternion floating joint");
                  app.add_flag("--json", options->json, "Print one JSON object instead of text");
                  return [options]() { return Run(*options); };
                });
}

}  // namespace cairn::cli
