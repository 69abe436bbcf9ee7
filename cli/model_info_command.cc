// `cairn model-info <urdf>`: loads a URDF into a multibody Model and summarises it (bodies, joints, nq/nv,
// total mass, centre of mass at the zero configuration, frames), as text or JSON.

#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

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

std::string JsonString(const std::string& text) {
  std::string out = "\"";
  for (const char c : text) {
    switch (c) {
      case '"':
        out += "\\\"";
        break;
      case '\\':
        out += "\\\\";
        break;
      case '\n':
        out += "\\n";
        break;
      default:
        if (static_cast<unsigned char>(c) < 0x20) {
          char buffer[8];
          std::snprintf(buffer, sizeof(buffer), "\\u%04x", c);
          out += buffer;
        } else {
          out += c;
        }
    }
  }
  return out + "\"";
}

// JSON has no infinity; unlimited joints report null.
std::string JsonNumber(double x) {
  if (!std::isfinite(x)) return "null";
  char buffer[32];
  std::snprintf(buffer, sizeof(buffer), "%.9g", x);
  return buffer;
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
    out << "{\"name\": " << JsonString(model.name()) << ", \"file\": " << JsonString(options.urdf)
        << ", \"nq\": " << model.nq() << ", \"nv\": " << model.nv()
        << ", \"total_mass\": " << JsonNumber(model.total_mass()) << ", \"com_at_zero\": "
        << (has_mass ? "[" + JsonNumber(com.x()) + ", " + JsonNumber(com.y()) + ", " + JsonNumber(com.z()) + "]"
                     : std::string("null"))
        << ",\n \"bodies\": [";
    for (int b = 0; b < model.num_bodies(); ++b) {
      const multibody::Body& body = model.body(b);
      out << (b ? ",\n   " : "\n   ") << "{\"name\": " << JsonString(body.name)
          << ", \"mass\": " << JsonNumber(body.inertia.mass())
          << ", \"parent\": " << (b ? JsonString(model.body(model.parent(b)).name) : std::string("null"))
          << ", \"collisions\": " << body.collisions.size() << ", \"visuals\": " << body.visuals.size() << "}";
    }
    out << "],\n \"joints\": [";
    for (int j = 1; j < model.num_bodies(); ++j) {
      const multibody::Joint& joint = model.joint(j);
      out << (j > 1 ? ",\n   " : "\n   ") << "{\"name\": " << JsonString(joint.name)
          << ", \"type\": " << JsonString(joint.continuous ? "continuous" : multibody::JointTypeName(joint.type))
          << ", \"parent\": " << JsonString(model.body(joint.parent).name)
          << ", \"child\": " << JsonString(model.body(j).name) << ", \"idx_q\": " << joint.idx_q
          << ", \"idx_v\": " << joint.idx_v << ", \"lower\": " << JsonNumber(joint.lower_limit)
          << ", \"upper\": " << JsonNumber(joint.upper_limit) << ", \"velocity\": " << JsonNumber(joint.velocity_limit)
          << ", \"effort\": " << JsonNumber(joint.effort_limit) << "}";
    }
    out << "],\n \"frames\": [";
    for (int f = 0; f < model.num_frames(); ++f) {
      out << (f ? ", " : "") << "{\"name\": " << JsonString(model.frame(f).name)
          << ", \"body\": " << JsonString(model.body(model.frame(f).body).name) << "}";
    }
    out << "]}\n";
    std::cout << out.str();
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
