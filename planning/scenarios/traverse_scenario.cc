#include "cairn/planning/scenarios/traverse_scenario.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "cairn/common/internal/yaml_reader.h"
#include "cairn/common/number_text.h"
#include "cairn/perception/terrain/collapsibility_estimator.h"

namespace cairn::planning {
namespace {

using cairn::internal::YamlReader;

double InRange(const YamlReader& yaml, const YAML::Node& node, const std::string& where, const std::string& key,
               double fallback, double lo, double hi, const std::string& unit) {
  const double v = yaml.Number(node, key, where, fallback);
  if (!(v >= lo && v <= hi)) {
    throw yaml.Error(node[key] ? node[key] : node, where + ": '" + key + "' must be in [" + FormatShort(lo) + ", " +
                                                       FormatShort(hi) + "]" + unit + ", got " + FormatShort(v) + ".");
  }
  return v;
}

Eigen::Vector2d Point(const YamlReader& yaml, const YAML::Node& node, const std::string& key, const std::string& where) {
  const Eigen::VectorXd v = yaml.Numbers(yaml.Require(node, key, where), key, 2);
  for (int i = 0; i < 2; ++i) {
    if (std::abs(v[i]) > 1e4) {
      throw yaml.Error(node[key], where + ": '" + key + "' coordinates must be within +-10000 m, got " +
                                      FormatShort(v[i]) + ".");
    }
  }
  return v;
}

TraverseScenario Parse(const YamlReader& yaml) {
  TraverseScenario s;
  const YAML::Node& root = yaml.root();
  yaml.CheckKeys(root, {"world", "start", "goal", "sensor", "robot", "probe", "planner", "regions"}, "the scenario");
  if (YamlReader::Has(root, "world")) {
    const YAML::Node w = root["world"];
    yaml.CheckKeys(w, {"min", "size", "resolution"}, "world");
    if (YamlReader::Has(w, "min")) s.world_min = Point(yaml, w, "min", "world");
    if (YamlReader::Has(w, "size")) s.world_size = Point(yaml, w, "size", "world");
    s.resolution = InRange(yaml, w, "world", "resolution", s.resolution, 0.01, 10.0, " m");
    if (!(s.world_size.minCoeff() > 0.0)) throw yaml.Error(w, "world: 'size' must be positive in x and y.");
    const double cells = std::ceil(s.world_size.x() / s.resolution) * std::ceil(s.world_size.y() / s.resolution);
    if (cells > static_cast<double>(TraverseScenario::kMaxCells)) {
      throw yaml.Error(w, "world: " + FormatShort(cells) + " cells (size / resolution) exceed the limit of " +
                              FormatShort(TraverseScenario::kMaxCells) + "; use a coarser resolution.");
    }
  }
  const auto inside = [&](const Eigen::Vector2d& p) {
    return (p.array() >= s.world_min.array()).all() && (p.array() < (s.world_min + s.world_size).array()).all();
  };
  s.start = Point(yaml, root, "start", "the scenario");
  s.goal = Point(yaml, root, "goal", "the scenario");
  if (!inside(s.start)) throw yaml.Error(root["start"], "the start is outside the world; move it or enlarge 'world'.");
  if (!inside(s.goal)) throw yaml.Error(root["goal"], "the goal is outside the world; move it or enlarge 'world'.");
  if (YamlReader::Has(root, "sensor")) {
    const YAML::Node n = root["sensor"];
    yaml.CheckKeys(n, {"range", "height", "point_spacing", "segmentation_confidence", "seed"}, "sensor");
    s.sensor_range = InRange(yaml, n, "sensor", "range", s.sensor_range, 0.2, 50.0, " m");
    s.sensor_height = InRange(yaml, n, "sensor", "height", s.sensor_height, 0.05, 10.0, " m");
    s.point_spacing = InRange(yaml, n, "sensor", "point_spacing", s.point_spacing, 0.005, 1.0, " m");
    s.segmentation_confidence =
        InRange(yaml, n, "sensor", "segmentation_confidence", s.segmentation_confidence, 0.5, 1.0, "");
    s.seed = static_cast<int>(yaml.Integer(n, "seed", "sensor", 0, 1 << 30, s.seed));
    const double points = M_PI * s.sensor_range * s.sensor_range / (s.point_spacing * s.point_spacing);
    if (points > static_cast<double>(TraverseScenario::kMaxPointsPerScan)) {
      throw yaml.Error(n, "sensor: about " + FormatShort(points) + " points per scan (range and point_spacing) " +
                              "exceed the limit of " + FormatShort(TraverseScenario::kMaxPointsPerScan) + ".");
    }
  }
  if (YamlReader::Has(root, "robot")) {
    const YAML::Node n = root["robot"];
    yaml.CheckKeys(n, {"step", "max_ticks"}, "robot");
    s.step = InRange(yaml, n, "robot", "step", s.step, 0.01, 5.0, " m");
    s.max_ticks = static_cast<int>(yaml.Integer(n, "max_ticks", "robot", 1, TraverseScenario::kMaxTicks, s.max_ticks));
  }
  if (YamlReader::Has(root, "probe")) {
    const YAML::Node n = root["probe"];
    yaml.CheckKeys(n, {"model", "depth", "hard_force", "noise", "samples", "reach", "ground_stiffness", "damping"},
                   "probe");
    if (YamlReader::Has(n, "model")) {
      const std::string model = yaml.String(n, "model", "probe");
      if (model == "plant") {
        s.probe_model = TraverseScenario::ProbeModel::kPlant;
      } else if (model == "spring") {
        s.probe_model = TraverseScenario::ProbeModel::kSpring;
      } else {
        throw yaml.Error(n["model"], "probe: model '" + model + "' is not one of plant, spring.");
      }
    }
    s.probe_damping = InRange(yaml, n, "probe", "damping", s.probe_damping, 0.0, 1e6, " N s/m");
    s.probe_depth = InRange(yaml, n, "probe", "depth", s.probe_depth, 1e-4, 1.0, " m");
    s.hard_force = InRange(yaml, n, "probe", "hard_force", s.hard_force, 1.0, 1e4, " N");
    s.force_noise = InRange(yaml, n, "probe", "noise", s.force_noise, 0.0, 1e3, " N");
    s.probe_samples =
        static_cast<int>(yaml.Integer(n, "samples", "probe", 1, TraverseScenario::kMaxProbeSamples, s.probe_samples));
    s.reach = InRange(yaml, n, "probe", "reach", s.reach, 0.05, 10.0, " m");
    s.ground_stiffness = InRange(yaml, n, "probe", "ground_stiffness", s.ground_stiffness, 0.0, 1e9, " N/m");
  }
  if (YamlReader::Has(root, "planner")) {
    const YAML::Node n = root["planner"];
    yaml.CheckKeys(n, {"blocked_below"}, "planner");
    s.blocked_below = InRange(yaml, n, "planner", "blocked_below", s.blocked_below, 0.0, 1.0, "");
  }
  if (YamlReader::Has(root, "regions")) {
    const YAML::Node list = root["regions"];
    if (!list.IsSequence()) throw yaml.Error(list, "'regions' must be a list of regions.");
    if (list.size() > TraverseScenario::kMaxRegions) {
      throw yaml.Error(list, FormatShort(static_cast<unsigned long>(list.size())) + " regions exceed the limit of " +
                                 FormatShort(static_cast<unsigned long>(TraverseScenario::kMaxRegions)) + ".");
    }
    int index = 0;
    for (const YAML::Node& r : list) {
      const std::string where = "region " + FormatShort(index++);
      yaml.CheckKeys(r, {"name", "kind", "box", "stiffness", "rock_height"}, where);
      TraverseScenario::Region region;
      region.name = yaml.String(r, "name", where, where);
      const std::string kind = yaml.String(r, "kind", where);
      if (kind == "rocks") {
        region.kind = TraverseScenario::Kind::kRocks;
      } else if (kind == "plants") {
        region.kind = TraverseScenario::Kind::kPlants;
      } else if (kind == "water") {
        region.kind = TraverseScenario::Kind::kWater;
      } else {
        throw yaml.Error(r["kind"], where + ": kind '" + kind + "' is not one of rocks, plants, water.");
      }
      const YAML::Node box = yaml.Require(r, "box", where);
      yaml.CheckKeys(box, {"min", "max"}, where + "'s box");
      region.min = Point(yaml, box, "min", where + "'s box");
      region.max = Point(yaml, box, "max", where + "'s box");
      if (!(region.max.array() > region.min.array()).all()) {
        throw yaml.Error(box, where + "'s box must have max > min in x and y.");
      }
      if (region.kind == TraverseScenario::Kind::kRocks) {
        if (YamlReader::Has(r, "stiffness")) throw yaml.Error(r["stiffness"], where + ": rocks take no 'stiffness'.");
        region.rock_height = InRange(yaml, r, where, "rock_height", region.rock_height, 0.0, 5.0, " m");
      } else {
        if (YamlReader::Has(r, "rock_height")) {
          throw yaml.Error(r["rock_height"], where + ": only rocks take 'rock_height'.");
        }
        region.stiffness = InRange(yaml, r, where, "stiffness", std::nan(""), 0.0, 1e9, " N/m");
      }
      s.regions.push_back(region);
    }
  }
  return s;
}

}  // namespace

TraverseScenario TraverseScenario::Load(const std::string& path) { return Parse(YamlReader(path, kMaxFileBytes)); }

TraverseScenario TraverseScenario::FromText(const std::string& path, const std::string& text) {
  if (text.size() > kMaxFileBytes) {
    throw std::invalid_argument("Scenario '" + path + "' has " + FormatShort(static_cast<unsigned long>(text.size())) +
                                " bytes, more than the limit of " +
                                FormatShort(static_cast<unsigned long>(kMaxFileBytes)));
  }
  return Parse(YamlReader::FromText(path, text));
}

const TraverseScenario::Region* TraverseScenario::RegionAt(const Eigen::Vector2d& p) const {
  for (const Region& r : regions) {
    if (r.Contains(p)) return &r;
  }
  return nullptr;
}

double TraverseScenario::HeightAt(const Eigen::Vector2d& p) const {
  const Region* r = RegionAt(p);
  if (r == nullptr || r->kind != Kind::kRocks) return 0.0;
  // Bumps of 0.4 m period: rough at a foot's scale, the way a rock field is.
  const double k = 2.0 * M_PI / 0.4;
  return r->rock_height * 0.5 * (1.0 + std::sin(k * p.x()) * std::sin(k * p.y()));
}

int TraverseScenario::ClassAt(const Eigen::Vector2d& p) const {
  const Region* r = RegionAt(p);
  if (r == nullptr || r->kind == Kind::kRocks) return -1;
  return r->kind == Kind::kPlants ? 0 : 1;
}

double TraverseScenario::StiffnessAt(const Eigen::Vector2d& p) const {
  const Region* r = RegionAt(p);
  if (r == nullptr || r->kind == Kind::kRocks) return ground_stiffness;
  return r->stiffness;
}

double TraverseScenario::TrueCollapsibility(const Eigen::Vector2d& p) const {
  return perception::CollapsibilityEstimator::FromForce(StiffnessAt(p) * probe_depth, hard_force);
}

std::string TraverseScenario::KindName(Kind kind) {
  switch (kind) {
    case Kind::kRocks: return "rocks";
    case Kind::kPlants: return "plants";
    case Kind::kWater: return "water";
  }
  return "?";
}

}  // namespace cairn::planning
