#include "cairn/planning/locomotion/walking_model.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <utility>
#include <vector>

#include "cairn/common/hash.h"
#include "cairn/common/internal/yaml_reader.h"
#include "cairn/common/number_text.h"
#include "cairn/common/text_suggestions.h"
#include "cairn/multibody/center_of_mass.h"
#include "cairn/multibody/configuration.h"
#include "cairn/multibody/data.h"
#include "cairn/multibody/kinematics.h"
#include "cairn/multibody/urdf_parser.h"

namespace cairn::planning {

struct WalkingModel::Impl {
  explicit Impl(multibody::Model parsed) : model(std::move(parsed)) {}
  std::string name;
  std::string yaml_path;
  std::string urdf_path;
  std::uint64_t hash{0};
  multibody::Model model;
  double mass{0.0};
  double gravity{0.0};
  StepReach reach;
  StepParameters lower, upper;
  double foot_length{0.0}, foot_width{0.0};
  Eigen::Vector3d body_half_extents{Eigen::Vector3d::Zero()};
  double body_box_bottom{0.0};
  LegGeometry leg;
  std::array<MotorConstants, kLegJoints> motors;
  std::array<std::string, kLegJoints> left_leg_joints;
  double swing_height{0.0};
  LegTorqueTable leg_torques;
};

namespace {

using cairn::internal::YamlReader;

constexpr double kPi = 3.14159265358979323846;

std::string Num(double x) { return FormatShort(x); }

std::string ReadFile(const std::string& path, const std::string& what) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("Cannot read the " + what + " '" + path + "'; check the path.");
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// Reads keys of the walking YAML on top of the common reader; messages name the key by its path ("reach.dx")
// after the file and line.
class Reader {
 public:
  explicit Reader(const YamlReader& yaml) : yaml_(yaml) {}

  [[noreturn]] void Fail(const std::string& key, const YAML::Node& node, const std::string& message) const {
    yaml_.Fail(node, "key '" + key + "': " + message);
  }

  // `prefix` is the mapping's key path with a trailing dot ("reach."), "" for the top level.
  void CheckKeys(const YAML::Node& map, const std::string& prefix, const std::vector<std::string>& known) const {
    yaml_.CheckKeys(map, known, prefix.empty() ? "the walking model" : "'" + prefix.substr(0, prefix.size() - 1) + "'");
  }

  YAML::Node Child(const YAML::Node& map, const std::string& prefix, const std::string& key) const {
    if (!YamlReader::Has(map, key)) Fail(prefix + key, map, "missing; see data/robots/README.md.");
    return map[key];
  }

  std::string String(const YAML::Node& map, const std::string& prefix, const std::string& key) const {
    return yaml_.AsString(Child(map, prefix, key), prefix + key);
  }

  double Number(const YAML::Node& node, const std::string& key) const { return yaml_.AsNumber(node, key); }

  double Number(const YAML::Node& map, const std::string& prefix, const std::string& key, double lo, double hi) const {
    const YAML::Node node = Child(map, prefix, key);
    const double value = Number(node, prefix + key);
    if (value < lo || value > hi) {
      Fail(prefix + key, node, Num(value) + " is outside its valid range [" + Num(lo) + ", " + Num(hi) + "].");
    }
    return value;
  }

  int Integer(const YAML::Node& map, const std::string& prefix, const std::string& key, int lo, int hi) const {
    return static_cast<int>(yaml_.AsInteger(Child(map, prefix, key), prefix + key, lo, hi));
  }

  // [min, max] within [lo, hi] with min <= max (min < max unless equal is allowed).
  std::pair<double, double> Range(const YAML::Node& map, const std::string& prefix, const std::string& key, double lo,
                                  double hi) const {
    const YAML::Node node = Child(map, prefix, key);
    if (!node.IsSequence() || node.size() != 2) Fail(prefix + key, node, "expected two numbers [min, max].");
    const double a = Number(node[0], prefix + key);
    const double b = Number(node[1], prefix + key);
    if (!(a <= b)) Fail(prefix + key, node, "min " + Num(a) + " is above max " + Num(b) + ".");
    if (a < lo || b > hi) {
      Fail(prefix + key, node,
           "[" + Num(a) + ", " + Num(b) + "] is outside its valid range [" + Num(lo) + ", " + Num(hi) + "].");
    }
    return {a, b};
  }

  std::vector<std::string> Strings(const YAML::Node& map, const std::string& prefix, const std::string& key,
                                   std::size_t count) const {
    return yaml_.Strings(Child(map, prefix, key), prefix + key, static_cast<int>(count));
  }

 private:
  const YamlReader& yaml_;
};

// Axis-aligned bounds of a collision shape in the world at the current poses.
void ExtendBounds(const multibody::Geometry& geometry, const multibody::Pose& X_WB, Eigen::Vector3d* lo,
                  Eigen::Vector3d* hi) {
  const multibody::Pose X_WG = X_WB * geometry.X_BG;
  const Eigen::Matrix3d& R = X_WG.rotation();
  Eigen::Vector3d half = Eigen::Vector3d::Zero();
  switch (geometry.type) {
    case multibody::GeometryType::kBox:
      half = R.cwiseAbs() * (0.5 * geometry.size);
      break;
    case multibody::GeometryType::kSphere:
      half.setConstant(geometry.radius);
      break;
    case multibody::GeometryType::kCapsule:
    case multibody::GeometryType::kCylinder:
      half = (0.5 * geometry.length) * R.col(2).cwiseAbs() + Eigen::Vector3d::Constant(geometry.radius);
      break;
    case multibody::GeometryType::kMesh:
      return;  // meshes carry no extent without loading them; the humanoid has none
  }
  *lo = lo->cwiseMin(X_WG.translation() - half);
  *hi = hi->cwiseMax(X_WG.translation() + half);
}

double LegLength(double thigh, double shank, double knee_flexion) {
  return std::sqrt(thigh * thigh + shank * shank + 2.0 * thigh * shank * std::cos(knee_flexion));
}

}  // namespace

WalkingModel::WalkingModel(std::shared_ptr<const Impl> impl) : impl_(std::move(impl)) {}

WalkingModel WalkingModel::Load(const std::string& yaml_path) {
  const YamlReader yaml(yaml_path);
  const YAML::Node& root = yaml.root();
  const Reader r(yaml);
  r.CheckKeys(root, "",
              {"name", "urdf", "pelvis_body", "sole_frames", "left_leg_joints", "right_leg_joints", "reach",
               "parameters", "knee_flexion_deg", "swing_height", "body_box", "leg_torque_grid", "motors"});

  const std::string name = r.String(root, "", "name");
  // The name becomes part of file names (the oracle cache) and of the oracle file's header lines.
  constexpr std::size_t kMaxNameLength = 64;
  const bool plain = std::all_of(name.begin(), name.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_' || c == '-' || c == '.';
  });
  if (name.empty() || name.size() > kMaxNameLength || !plain || name[0] == '.') {
    r.Fail("name", root["name"], "must be 1 to " + cairn::FormatShort(kMaxNameLength) +
                                     " letters, digits, '_', '-' or '.' (not first), as it names cache files; got '" +
                                     name.substr(0, kMaxNameLength) + (name.size() > kMaxNameLength ? "...'." : "'."));
  }
  const std::filesystem::path urdf_relative = r.String(root, "", "urdf");
  const std::filesystem::path urdf =
      urdf_relative.is_absolute() ? urdf_relative : std::filesystem::path(yaml_path).parent_path() / urdf_relative;
  const std::string urdf_path = urdf.lexically_normal().string();
  if (!std::filesystem::exists(urdf_path)) {
    r.Fail("urdf", root["urdf"], "the file '" + urdf_path + "' does not exist (paths are relative to the YAML's folder).");
  }
  multibody::UrdfOptions urdf_options;
  urdf_options.floating_base = true;
  // The parser bounds what it reads (a device such as /dev/zero is refused), so the model is parsed before the
  // file's bytes are read again for the content hash.
  auto impl = std::make_shared<Impl>(multibody::ParseUrdfFile(urdf_path, urdf_options));
  const std::string urdf_text = ReadFile(urdf_path, "URDF");
  impl->name = name;
  impl->yaml_path = yaml_path;
  impl->urdf_path = urdf_path;
  impl->hash = Fnv1a64(urdf_text, Fnv1a64(yaml.text()));
  const multibody::Model& model = impl->model;
  impl->mass = model.total_mass();
  impl->gravity = model.gravity().norm();

  // Names, checked against the URDF.
  const std::string pelvis = r.String(root, "", "pelvis_body");
  if (!model.HasBody(pelvis)) {
    r.Fail("pelvis_body", root["pelvis_body"], "no body '" + pelvis + "' in " + impl->urdf_path + "; did you mean " +
                                                   QuotedList(ClosestNames(pelvis, model.body_names())) + "?");
  }
  if (model.body(1).name != pelvis) {
    r.Fail("pelvis_body", root["pelvis_body"], "'" + pelvis + "' is not the URDF's root link ('" + model.body(1).name +
                                                   "'); the pelvis must be the floating base.");
  }
  const std::vector<std::string> soles = r.Strings(root, "", "sole_frames", 2);
  for (const std::string& sole : soles) {
    if (!model.HasFrame(sole)) {
      r.Fail("sole_frames", root["sole_frames"], "no frame '" + sole + "' in " + impl->urdf_path + "; did you mean " +
                                                     QuotedList(ClosestNames(sole, model.frame_names())) + "?");
    }
  }
  std::array<std::vector<std::string>, 2> legs = {r.Strings(root, "", "left_leg_joints", kLegJoints),
                                                  r.Strings(root, "", "right_leg_joints", kLegJoints)};
  for (int side = 0; side < 2; ++side) {
    const char* key = side == 0 ? "left_leg_joints" : "right_leg_joints";
    for (const std::string& joint : legs[side]) {
      if (!model.HasJoint(joint)) {
        r.Fail(key, root[key], "no joint '" + joint + "' in " + impl->urdf_path + "; did you mean " +
                                   QuotedList(ClosestNames(joint, model.joint_names())) + "?");
      }
    }
  }
  for (int j = 0; j < kLegJoints; ++j) impl->left_leg_joints[j] = legs[0][j];

  // Leg geometry at the zero configuration (pelvis at the origin).
  multibody::Data data(model);
  const Eigen::VectorXd q0 = multibody::NeutralConfiguration(model);
  const Eigen::Vector3d com = multibody::CenterOfMass(model, data, q0);  // also runs the kinematics
  auto joint_origin = [&](const std::string& joint) -> Eigen::Vector3d {
    return data.X_world[model.GetJointIndex(joint)].translation();  // body i's frame = joint i's frame at zero
  };
  const Eigen::Vector3d hip = joint_origin(legs[0][1]);
  const Eigen::Vector3d knee = joint_origin(legs[0][3]);
  const Eigen::Vector3d ankle = joint_origin(legs[0][4]);
  const multibody::Pose X_sole = multibody::FramePose(model, data, model.GetFrameIndex(soles[0]));
  LegGeometry& leg = impl->leg;
  leg.hip_from_com = hip - com;
  leg.thigh_length = (knee - hip).norm();
  leg.shank_length = (ankle - knee).norm();
  leg.ankle_height = ankle.z() - X_sole.translation().z();
  leg.ankle_forward = ankle.x() - X_sole.translation().x();
  leg.com_height_standing = com.z() - X_sole.translation().z();
  if (!(leg.thigh_length > 0.0 && leg.shank_length > 0.0 && leg.ankle_height > 0.0)) {
    throw std::runtime_error(yaml_path + ": the leg joints named in 'left_leg_joints' do not form a leg in " +
                             impl->urdf_path + " (thigh " + Num(leg.thigh_length) + " m, shank " +
                             Num(leg.shank_length) + " m, ankle height " + Num(leg.ankle_height) + " m).");
  }

  // Knee range and the leg lengths it allows.
  const auto knee_deg = r.Range(root, "", "knee_flexion_deg", 0.0, 170.0);
  if (!(knee_deg.second > knee_deg.first)) {
    r.Fail("knee_flexion_deg", root["knee_flexion_deg"], "needs min < max.");
  }
  leg.knee_flexion_min = knee_deg.first * kPi / 180.0;
  leg.knee_flexion_max = knee_deg.second * kPi / 180.0;
  leg.leg_length_max = LegLength(leg.thigh_length, leg.shank_length, leg.knee_flexion_min);
  leg.leg_length_min = LegLength(leg.thigh_length, leg.shank_length, leg.knee_flexion_max);

  // Reach.
  const YAML::Node reach = r.Child(root, "", "reach");
  r.CheckKeys(reach, "reach.", {"dx", "dy", "dz", "dtheta_deg"});
  const double leg_reach = leg.leg_length_max;
  const auto dx = r.Range(reach, "reach.", "dx", -leg_reach, 2.0 * leg_reach);
  const auto dy = r.Range(reach, "reach.", "dy", 0.0, 2.0 * leg_reach);
  const auto dz = r.Range(reach, "reach.", "dz", -leg_reach, leg_reach);
  const auto dtheta = r.Range(reach, "reach.", "dtheta_deg", -90.0, 90.0);
  impl->reach = StepReach{dx.first, dx.second, dy.first, dy.second, dz.first, dz.second,
                          dtheta.first * kPi / 180.0, dtheta.second * kPi / 180.0};

  // Feet: the sole's box is the collision box whose bottom face holds the sole frame.
  {
    const multibody::Frame& frame = model.frame(model.GetFrameIndex(soles[0]));
    bool found = false;
    for (int b = frame.body; b > 0 && !found; b = model.parent(b)) {  // the frame's body or an ancestor
      for (const multibody::Geometry& geometry : model.body(b).collisions) {
        if (geometry.type != multibody::GeometryType::kBox) continue;
        const multibody::Pose X_WG = data.X_world[b] * geometry.X_BG;
        const double bottom = X_WG.translation().z() - 0.5 * geometry.size.z();
        const Eigen::Vector2d offset = (X_WG.translation() - X_sole.translation()).head<2>();
        if (std::abs(bottom - X_sole.translation().z()) < 1e-6 && offset.norm() < 1e-6) {
          impl->foot_length = geometry.size.x();
          impl->foot_width = geometry.size.y();
          found = true;
        }
      }
    }
    if (!found) {
      throw std::runtime_error(yaml_path + ": no collision box of '" + model.body(frame.body).name +
                               "' or its ancestors is centred on the sole frame '" + soles[0] +
                               "' with its bottom face at the sole; the walking model needs the sole plate as a box.");
    }
  }
  if (impl->reach.dy_min < impl->foot_width) {
    r.Fail("reach.dy", reach["dy"], "the minimum " + Num(impl->reach.dy_min) + " m is below the sole width " +
                                        Num(impl->foot_width) + " m: the soles would overlap side by side.");
  }

  // Parameters.
  const YAML::Node parameters = r.Child(root, "", "parameters");
  r.CheckKeys(parameters, "parameters.", {"t_ds", "t_sw", "com_height"});
  const auto t_ds = r.Range(parameters, "parameters.", "t_ds", 1e-3, 10.0);
  const auto t_sw = r.Range(parameters, "parameters.", "t_sw", 1e-3, 10.0);
  const auto com_height = r.Range(parameters, "parameters.", "com_height", 0.05, 5.0);
  // COM heights the legs allow with the foot under the hip: the legs between the knee-range lengths.
  const double com_above_hip = com.z() - hip.z();
  const double com_height_lo = leg.ankle_height + leg.leg_length_min + com_above_hip;
  const double com_height_hi = leg.ankle_height + leg.leg_length_max + com_above_hip;
  if (com_height.first < com_height_lo - 1e-9 || com_height.second > com_height_hi + 1e-9) {
    r.Fail("parameters.com_height", parameters["com_height"],
           "[" + Num(com_height.first) + ", " + Num(com_height.second) + "] m is not reachable: with knee flexion in [" +
               Num(knee_deg.first) + ", " + Num(knee_deg.second) + "] degrees the legs put the COM between " +
               Num(com_height_lo) + " and " + Num(com_height_hi) + " m above the soles.");
  }
  impl->lower = StepParameters{t_ds.first, t_sw.first, com_height.first};
  impl->upper = StepParameters{t_ds.second, t_sw.second, com_height.second};

  impl->swing_height = r.Number(root, "", "swing_height", 0.0, leg.leg_length_max);

  // Body box above the knees.
  {
    const YAML::Node box = r.Child(root, "", "body_box");
    r.CheckKeys(box, "body_box.", {"crouch"});
    const double crouch = r.Number(box, "body_box.", "crouch", 0.0, 1.0);
    Eigen::Vector3d lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
    Eigen::Vector3d hi = -lo;
    const int left_knee = model.GetJointIndex(legs[0][3]);
    const int right_knee = model.GetJointIndex(legs[1][3]);
    for (int b = 1; b < model.num_bodies(); ++b) {
      if (model.IsAncestorOrSelf(left_knee, b) || model.IsAncestorOrSelf(right_knee, b)) continue;
      for (const multibody::Geometry& geometry : model.body(b).collisions) ExtendBounds(geometry, data.X_world[b], &lo, &hi);
    }
    const double sole_z = X_sole.translation().z();
    const double bottom = knee.z() - sole_z;
    const double top = hi.z() - sole_z - crouch;
    if (!(top > bottom)) {
      r.Fail("body_box.crouch", box["crouch"], Num(crouch) + " m leaves no box between the knees (" + Num(bottom) +
                                                  " m) and the top of the robot (" + Num(hi.z() - sole_z) + " m).");
    }
    impl->body_half_extents = Eigen::Vector3d(std::max(std::abs(lo.x()), std::abs(hi.x())),
                                              std::max(std::abs(lo.y()), std::abs(hi.y())), 0.5 * (top - bottom));
    impl->body_box_bottom = bottom;
  }

  // Motors.
  {
    const YAML::Node motors = r.Child(root, "", "motors");
    const std::vector<std::string> keys = {"hip_yaw", "hip_roll", "hip_pitch", "knee", "ankle_pitch", "ankle_roll"};
    r.CheckKeys(motors, "motors.", keys);
    for (int j = 0; j < kLegJoints; ++j) {
      const YAML::Node motor = r.Child(motors, "motors.", keys[j]);
      const std::string prefix = "motors." + keys[j] + ".";
      r.CheckKeys(motor, prefix, {"resistance", "torque_constant", "gear_ratio"});
      MotorConstants& m = impl->motors[j];
      m.resistance = r.Number(motor, prefix, "resistance", 1e-6, 1e3);
      m.torque_constant = r.Number(motor, prefix, "torque_constant", 1e-6, 10.0);
      m.gear_ratio = r.Number(motor, prefix, "gear_ratio", 1.0, 1e4);
    }
  }

  // Static leg torques over the postures the legs may take.
  {
    const YAML::Node grid_node = r.Child(root, "", "leg_torque_grid");
    r.CheckKeys(grid_node, "leg_torque_grid.", {"length_count", "pitch_deg", "pitch_count", "roll_deg", "roll_count"});
    LegTorqueGrid grid;
    grid.length_min = leg.leg_length_min;
    grid.length_max = leg.leg_length_max;
    grid.length_count = r.Integer(grid_node, "leg_torque_grid.", "length_count", 2, 100);
    const auto pitch = r.Range(grid_node, "leg_torque_grid.", "pitch_deg", -80.0, 80.0);
    const auto roll = r.Range(grid_node, "leg_torque_grid.", "roll_deg", -80.0, 80.0);
    grid.pitch_min = pitch.first * kPi / 180.0;
    grid.pitch_max = pitch.second * kPi / 180.0;
    grid.roll_min = roll.first * kPi / 180.0;
    grid.roll_max = roll.second * kPi / 180.0;
    grid.pitch_count = r.Integer(grid_node, "leg_torque_grid.", "pitch_count", 2, 200);
    grid.roll_count = r.Integer(grid_node, "leg_torque_grid.", "roll_count", 2, 200);
    std::array<std::string, kLegJoints> names;
    for (int j = 0; j < kLegJoints; ++j) names[j] = legs[0][j];
    try {
      impl->leg_torques = LegTorqueTable::Compute(model, names, soles[0], grid);
    } catch (const std::exception& error) {
      r.Fail("leg_torque_grid", grid_node, error.what());
    }
  }
  return WalkingModel(std::move(impl));
}

const std::string& WalkingModel::name() const { return impl_->name; }
double WalkingModel::mass() const { return impl_->mass; }
double WalkingModel::gravity() const { return impl_->gravity; }
const StepReach& WalkingModel::reach() const { return impl_->reach; }
const StepParameters& WalkingModel::parameter_lower() const { return impl_->lower; }
const StepParameters& WalkingModel::parameter_upper() const { return impl_->upper; }
double WalkingModel::foot_length() const { return impl_->foot_length; }
double WalkingModel::foot_width() const { return impl_->foot_width; }
const Eigen::Vector3d& WalkingModel::body_half_extents() const { return impl_->body_half_extents; }
double WalkingModel::body_box_bottom() const { return impl_->body_box_bottom; }
const LegGeometry& WalkingModel::leg() const { return impl_->leg; }
const MotorConstants& WalkingModel::motor(int i) const {
  if (i < 0 || i >= kLegJoints) {
    throw std::out_of_range("WalkingModel::motor: leg joint " + cairn::FormatShort(i) + " is not in [0, 5].");
  }
  return impl_->motors[static_cast<std::size_t>(i)];
}
const std::array<std::string, WalkingModel::kLegJoints>& WalkingModel::left_leg_joint_names() const {
  return impl_->left_leg_joints;
}
double WalkingModel::swing_height() const { return impl_->swing_height; }
const LegTorqueTable& WalkingModel::leg_torques() const { return impl_->leg_torques; }
const multibody::Model& WalkingModel::multibody() const { return impl_->model; }
std::uint64_t WalkingModel::content_hash() const { return impl_->hash; }
const std::string& WalkingModel::yaml_path() const { return impl_->yaml_path; }
const std::string& WalkingModel::urdf_path() const { return impl_->urdf_path; }

}  // namespace cairn::planning
