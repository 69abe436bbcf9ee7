#include "cairn/common/number_text.h"
#include "cairn/perception/synthetic/occupancy_scenario.h"

#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include "cairn/common/internal/yaml_reader.h"
#include "cairn/common/number_text.h"
#include "cairn/common/text_suggestions.h"

namespace cairn::perception {
namespace {

using cairn::internal::YamlReader;

// Larger grids are almost certainly a typo in `resolution` or `dims` (4 bytes of log-odds per cell, plus the
// per-thread accumulators of the sensor models).
constexpr double kMaxGridCells = 64.0e6;

// Reads typed values on top of the common reader; messages name the key path ("objects[1].half_extents") after the
// file and line, and point at the schema.
class Reader {
 public:
  explicit Reader(const YamlReader& yaml) : yaml_(yaml) {}

  [[noreturn]] void Fail(const YAML::Node& node, const std::string& key, const std::string& message) const {
    yaml_.Fail(node, "'" + key + "' " + message + " (schema: docs/occupancy_scenarios.md)");
  }

  // `map` must be a map whose keys are all in `allowed`; a misspelt key is reported with the closest name.
  void CheckMap(const YAML::Node& map, const std::string& where, const std::vector<std::string>& allowed) const {
    yaml_.CheckKeys(map, allowed, where.empty() ? "the scenario" : "'" + where + "'");
  }

  YAML::Node Required(const YAML::Node& map, const std::string& where, const std::string& key) const {
    if (!YamlReader::Has(map, key)) Fail(map, Join(where, key), "is missing");
    return map[key];
  }

  double Number(const YAML::Node& node, const std::string& key) const { return yaml_.AsNumber(node, key); }

  double Positive(const YAML::Node& node, const std::string& key) const {
    const double value = Number(node, key);
    if (!(value > 0.0)) Fail(node, key, "must be positive, got " + node.Scalar());
    return value;
  }

  // An integer in [min_value, max_value] (the common reader names 2^40 as out of range, not "not an integer").
  std::int64_t Integer(const YAML::Node& node, const std::string& key, std::int64_t min_value,
                       std::int64_t max_value) const {
    return yaml_.AsInteger(node, key, min_value, max_value);
  }
  int Integer(const YAML::Node& node, const std::string& key, int min_value) const {
    return static_cast<int>(Integer(node, key, min_value, std::numeric_limits<int>::max()));
  }
  // A seed: every value of std::uint32_t, no more (a larger one would wrap round to another seed).
  std::uint32_t Seed(const YAML::Node& node, const std::string& key) const {
    return static_cast<std::uint32_t>(Integer(node, key, 0, std::numeric_limits<std::uint32_t>::max()));
  }

  // Coordinates and lengths in metres, bounded so that products and norms stay finite.
  Eigen::Vector3d Vector3(const YAML::Node& node, const std::string& key) const {
    const Eigen::Vector3d v = yaml_.Numbers(node, key, 3);
    for (int i = 0; i < 3; ++i) {
      if (!(std::abs(v[i]) <= OccupancyScenario::kMaxCoordinate)) {
        Fail(node, key + "[" + cairn::FormatShort(i) + "]",
             "is " + FormatShort(v[i]) + ", beyond the +-" + FormatShort(OccupancyScenario::kMaxCoordinate) +
                 " a scenario may use");
      }
    }
    return v;
  }
  double Bounded(const YAML::Node& node, const std::string& key) const {
    const double value = Number(node, key);
    if (!(std::abs(value) <= OccupancyScenario::kMaxCoordinate)) {
      Fail(node, key, "is " + FormatShort(value) + ", beyond the +-" + FormatShort(OccupancyScenario::kMaxCoordinate) +
                          " a scenario may use");
    }
    return value;
  }
  // A list with at most `limit` entries, checked before any of them is read.
  void CheckCount(const YAML::Node& list, const std::string& key, std::size_t limit) const {
    if (list.size() > limit) {
      Fail(list, key, "has " + cairn::FormatShort(list.size()) + " entries, more than the " + cairn::FormatShort(limit) +
                          " a scenario may have");
    }
  }

  static std::string Join(const std::string& where, const std::string& key) {
    return where.empty() ? key : where + "." + key;
  }

 private:
  const YamlReader& yaml_;
};

ProceduralTexture ReadTexture(const Reader& r, const YAML::Node& node, const std::string& where) {
  r.CheckMap(node, where, {"kind", "scale", "mean", "contrast", "seed"});
  ProceduralTexture texture;
  const YAML::Node kind = r.Required(node, where, "kind");
  const std::string name = kind.IsScalar() ? kind.Scalar() : std::string();
  if (name == "noise") {
    texture.kind = ProceduralTexture::Kind::kNoise;
  } else if (name == "checker") {
    texture.kind = ProceduralTexture::Kind::kChecker;
  } else if (name == "uniform") {
    texture.kind = ProceduralTexture::Kind::kUniform;
  } else {
    r.Fail(kind, Reader::Join(where, "kind"), "is '" + name + "'; expected 'noise', 'checker' or 'uniform'");
  }
  if (node["scale"]) {
    texture.scale = r.Positive(node["scale"], Reader::Join(where, "scale"));
    r.Bounded(node["scale"], Reader::Join(where, "scale"));
  }
  if (node["mean"]) {
    texture.mean = r.Number(node["mean"], Reader::Join(where, "mean"));
    if (texture.mean < 0.0 || texture.mean > 255.0) {
      r.Fail(node["mean"], Reader::Join(where, "mean"), "must be an intensity in [0, 255]");
    }
  }
  if (node["contrast"]) {
    texture.contrast = r.Number(node["contrast"], Reader::Join(where, "contrast"));
    if (texture.contrast < 0.0 || texture.contrast > 127.5) {
      r.Fail(node["contrast"], Reader::Join(where, "contrast"), "must be in [0, 127.5] (peak deviation from the mean)");
    }
  }
  if (node["seed"]) texture.seed = r.Seed(node["seed"], Reader::Join(where, "seed"));
  return texture;
}

Eigen::Matrix3d RollPitchYawDegrees(const Eigen::Vector3d& rpy) {
  const Eigen::Vector3d a = rpy * M_PI / 180.0;
  return (Eigen::AngleAxisd(a.z(), Eigen::Vector3d::UnitZ()) * Eigen::AngleAxisd(a.y(), Eigen::Vector3d::UnitY()) *
          Eigen::AngleAxisd(a.x(), Eigen::Vector3d::UnitX()))
      .toRotationMatrix();
}

Eigen::Isometry3d ReadLookAt(const Reader& r, const YAML::Node& node, const std::string& where,
                             const Eigen::Vector3d& position, const Eigen::Vector3d& target) {
  try {
    return OccupancyScenario::LookAt(position, target);
  } catch (const std::invalid_argument& error) {
    r.Fail(node, where, error.what());
  }
}

}  // namespace

Eigen::Isometry3d OccupancyScenario::LookAt(const Eigen::Vector3d& position, const Eigen::Vector3d& target) {
  const Eigen::Vector3d offset = target - position;
  if (!(offset.norm() > 1e-9)) {
    throw std::invalid_argument("the camera position and the point it looks at coincide; move one of them");
  }
  const Eigen::Vector3d forward = offset.normalized();
  const Eigen::Vector3d right_raw = forward.cross(Eigen::Vector3d::UnitZ());
  if (right_raw.norm() < 1e-6) {
    throw std::invalid_argument("the camera looks straight up or down, so the world's +z cannot be 'up' in the image; "
                                "tilt the view");
  }
  const Eigen::Vector3d right = right_raw.normalized();
  Eigen::Isometry3d X_WC = Eigen::Isometry3d::Identity();
  X_WC.linear().col(0) = right;
  X_WC.linear().col(1) = forward.cross(right);  // image y: down
  X_WC.linear().col(2) = forward;
  X_WC.translation() = position;
  return X_WC;
}

OccupancyScenario OccupancyScenario::FromYaml(const std::string& path) {
  const YamlReader yaml(path, kMaxFileBytes);
  const YAML::Node& root = yaml.root();
  const Reader r(yaml);
  r.CheckMap(root, "", {"camera", "stereo", "noise_variance", "seed", "textures", "objects", "trajectory", "grid"});
  OccupancyScenario s;

  // Camera.
  const YAML::Node camera = r.Required(root, "", "camera");
  r.CheckMap(camera, "camera", {"width", "height", "fx", "fy", "cx", "cy", "baseline"});
  s.width = static_cast<int>(r.Integer(r.Required(camera, "camera", "width"), "camera.width", 16, kMaxImageSide));
  s.height = static_cast<int>(r.Integer(r.Required(camera, "camera", "height"), "camera.height", 16, kMaxImageSide));
  s.calibration.fx = r.Positive(r.Required(camera, "camera", "fx"), "camera.fx");
  s.calibration.fy = camera["fy"] ? r.Positive(camera["fy"], "camera.fy") : s.calibration.fx;
  s.calibration.cx = camera["cx"] ? r.Bounded(camera["cx"], "camera.cx") : 0.5 * (s.width - 1);
  s.calibration.cy = camera["cy"] ? r.Bounded(camera["cy"], "camera.cy") : 0.5 * (s.height - 1);
  s.calibration.baseline = r.Positive(r.Required(camera, "camera", "baseline"), "camera.baseline");
  r.Bounded(camera["baseline"], "camera.baseline");

  // Stereo matching range.
  const YAML::Node stereo = r.Required(root, "", "stereo");
  r.CheckMap(stereo, "stereo", {"min_disparity", "max_disparity"});
  s.min_disparity = r.Integer(r.Required(stereo, "stereo", "min_disparity"), "stereo.min_disparity", 1);
  const YAML::Node max_disparity = r.Required(stereo, "stereo", "max_disparity");
  s.max_disparity = r.Integer(max_disparity, "stereo.max_disparity", s.min_disparity + 1);
  if (s.max_disparity >= s.width) {
    r.Fail(max_disparity, "stereo.max_disparity",
           "is " + cairn::FormatShort(s.max_disparity) + " but the image is only " + cairn::FormatShort(s.width) +
               " px wide; lower it or widen the camera");
  }

  // Noise.
  if (root["noise_variance"]) {
    s.noise_variance = r.Number(root["noise_variance"], "noise_variance");
    if (!(s.noise_variance >= 0.0 && s.noise_variance <= kMaxNoiseVariance)) {
      r.Fail(root["noise_variance"], "noise_variance",
             "must be in [0, " + FormatShort(kMaxNoiseVariance) + "] (0: noise-free; 255^2 drowns every intensity)");
    }
  }
  if (root["seed"]) s.seed = r.Seed(root["seed"], "seed");

  // Named textures, then objects.
  std::map<std::string, ProceduralTexture> textures;
  if (const YAML::Node named = root["textures"]) {
    if (!named.IsMap()) r.Fail(named, "textures", "must be a map from texture names to textures");
    r.CheckCount(named, "textures", kMaxTextures);
    for (const auto& entry : named) {
      const std::string name = entry.first.Scalar();
      textures[name] = ReadTexture(r, entry.second, "textures." + name);
    }
  }
  std::vector<std::string> texture_names;
  for (const auto& [name, texture] : textures) texture_names.push_back(name);

  const YAML::Node objects = r.Required(root, "", "objects");
  if (!objects.IsSequence() || objects.size() == 0) {
    r.Fail(objects, "objects", "must be a non-empty list of planes and boxes");
  }
  r.CheckCount(objects, "objects", kMaxObjects);
  for (std::size_t i = 0; i < objects.size(); ++i) {
    const YAML::Node object = objects[i];
    const std::string where = "objects[" + cairn::FormatShort(i) + "]";
    if (!object.IsMap()) r.Fail(object, where, "must be a map with a 'type' key ('plane' or 'box')");
    const YAML::Node type = r.Required(object, where, "type");
    const std::string kind = type.IsScalar() ? type.Scalar() : std::string();
    if (kind == "plane") {
      r.CheckMap(object, where, {"type", "point", "normal", "texture", "label"});
    } else if (kind == "box") {
      r.CheckMap(object, where, {"type", "center", "half_extents", "rotation_rpy_deg", "texture", "label"});
    } else {
      r.Fail(type, where + ".type", "is '" + kind + "'; expected 'plane' or 'box'");
    }
    const YAML::Node texture_node = r.Required(object, where, "texture");
    ProceduralTexture texture;
    if (texture_node.IsScalar()) {
      const auto found = textures.find(texture_node.Scalar());
      if (found == textures.end()) {
        std::string message = "names texture '" + texture_node.Scalar() + "', which 'textures' does not define";
        message += texture_names.empty() ? "; define it there or give the texture inline"
                                         : "; defined: " + QuotedList(texture_names);
        r.Fail(texture_node, where + ".texture", message);
      }
      texture = found->second;
    } else {
      texture = ReadTexture(r, texture_node, where + ".texture");
    }
    const int label = static_cast<int>(r.Integer(r.Required(object, where, "label"), where + ".label", 0, kMaxLabel));
    if (kind == "plane") {
      const Eigen::Vector3d point = r.Vector3(r.Required(object, where, "point"), where + ".point");
      const YAML::Node normal_node = r.Required(object, where, "normal");
      const Eigen::Vector3d normal = r.Vector3(normal_node, where + ".normal");
      if (!(normal.norm() > 1e-12)) r.Fail(normal_node, where + ".normal", "is zero; give the plane's normal direction");
      s.scene.AddPlane(point, normal, texture, label);
    } else {
      Eigen::Isometry3d X_WB = Eigen::Isometry3d::Identity();
      X_WB.translation() = r.Vector3(r.Required(object, where, "center"), where + ".center");
      if (object["rotation_rpy_deg"]) {
        X_WB.linear() = RollPitchYawDegrees(r.Vector3(object["rotation_rpy_deg"], where + ".rotation_rpy_deg"));
      }
      const YAML::Node half_node = r.Required(object, where, "half_extents");
      const Eigen::Vector3d half = r.Vector3(half_node, where + ".half_extents");
      if (!(half.minCoeff() > 0.0)) r.Fail(half_node, where + ".half_extents", "must all be positive (metres)");
      s.scene.AddBox(X_WB, half, texture, label);
    }
  }

  // Trajectory.
  const YAML::Node trajectory = r.Required(root, "", "trajectory");
  r.CheckMap(trajectory, "trajectory", {"orbit", "poses"});
  if ((trajectory["orbit"] ? 1 : 0) + (trajectory["poses"] ? 1 : 0) != 1) {
    r.Fail(trajectory, "trajectory", "needs exactly one of 'orbit' and 'poses'");
  }
  if (const YAML::Node orbit = trajectory["orbit"]) {
    const std::string where = "trajectory.orbit";
    r.CheckMap(orbit, where, {"center", "radius", "height", "start_deg", "end_deg", "frames", "look_at"});
    const Eigen::Vector3d center = r.Vector3(r.Required(orbit, where, "center"), where + ".center");
    const double radius = r.Positive(r.Required(orbit, where, "radius"), where + ".radius");
    r.Bounded(orbit["radius"], where + ".radius");
    const double height = orbit["height"] ? r.Bounded(orbit["height"], where + ".height") : 0.0;
    const double start = r.Bounded(r.Required(orbit, where, "start_deg"), where + ".start_deg");
    const double end = r.Bounded(r.Required(orbit, where, "end_deg"), where + ".end_deg");
    // Bounded before the poses are built (a typo of 100000000 frames would need gigabytes).
    const int frames = static_cast<int>(r.Integer(r.Required(orbit, where, "frames"), where + ".frames", 1, kMaxFrames));
    const Eigen::Vector3d target = orbit["look_at"] ? r.Vector3(orbit["look_at"], where + ".look_at") : center;
    for (int f = 0; f < frames; ++f) {
      const double angle = (frames == 1 ? start : start + (end - start) * f / (frames - 1)) * M_PI / 180.0;
      const Eigen::Vector3d position =
          center + radius * Eigen::Vector3d(std::sin(angle), -std::cos(angle), 0.0) + height * Eigen::Vector3d::UnitZ();
      s.trajectory.push_back(ReadLookAt(r, orbit, where, position, target));
    }
  } else {
    const YAML::Node poses = trajectory["poses"];
    if (!poses.IsSequence() || poses.size() == 0) {
      r.Fail(poses, "trajectory.poses", "must be a non-empty list of {position, look_at}");
    }
    r.CheckCount(poses, "trajectory.poses", kMaxFrames);
    for (std::size_t k = 0; k < poses.size(); ++k) {
      const std::string where = "trajectory.poses[" + cairn::FormatShort(k) + "]";
      r.CheckMap(poses[k], where, {"position", "look_at"});
      const Eigen::Vector3d position = r.Vector3(r.Required(poses[k], where, "position"), where + ".position");
      const Eigen::Vector3d target = r.Vector3(r.Required(poses[k], where, "look_at"), where + ".look_at");
      s.trajectory.push_back(ReadLookAt(r, poses[k], where, position, target));
    }
  }

  // Evaluation grid.
  const YAML::Node grid = r.Required(root, "", "grid");
  r.CheckMap(grid, "grid", {"min_corner", "resolution", "dims"});
  s.grid_min_corner = r.Vector3(r.Required(grid, "grid", "min_corner"), "grid.min_corner");
  s.grid_resolution = r.Positive(r.Required(grid, "grid", "resolution"), "grid.resolution");
  r.Bounded(grid["resolution"], "grid.resolution");
  const YAML::Node dims = r.Required(grid, "grid", "dims");
  if (!dims.IsSequence() || dims.size() != 3) r.Fail(dims, "grid.dims", "must be a list of 3 cell counts [nx, ny, nz]");
  for (int a = 0; a < 3; ++a) s.grid_dims[a] = r.Integer(dims[a], "grid.dims[" + cairn::FormatShort(a) + "]", 1);
  const double cells = static_cast<double>(s.grid_dims.x()) * s.grid_dims.y() * s.grid_dims.z();
  if (cells > kMaxGridCells) {
    r.Fail(dims, "grid.dims",
           "gives " + cairn::FormatShort(static_cast<long long>(cells)) + " cells, more than the 64 million allowed; " +
               "use a coarser resolution or a smaller extent");
  }
  return s;
}

}  // namespace cairn::perception
