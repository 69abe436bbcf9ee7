#include <cairn/common/number_text.h>
#include <cairn/planning/scenarios/footstep_scenario.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

#include <cairn/common/number_text.h>
#include <cairn/perception/friction/material_registry.h>
#include <cairn/common/internal/yaml_reader.h>
#include <cairn/planning/footstep/time_limit_reached.h>

#include "cairn/common/number_text.h"

namespace cairn::planning {
namespace {

using cairn::internal::YamlReader;
using perception::FrictionDistribution;

constexpr double kDeg = M_PI / 180.0;

std::string Format(double value) { return FormatShort(value); }

// `value` (read from `node`, the key `key` of `where`) must lie in [lo, hi]; NaN never does.
void CheckRange(const YamlReader& yaml, const YAML::Node& node, const std::string& where, const std::string& key,
                double value, double lo, double hi, const std::string& unit) {
  if (!(value >= lo && value <= hi)) {
    throw yaml.Error(node, where + ": '" + key + "' must be in [" + Format(lo) + ", " + Format(hi) + "]" + unit +
                               ", got " + Format(value) + ".");
  }
}

// A horizontal position [x, y] within the coordinate bound.
void CheckPoint(const YamlReader& yaml, const YAML::Node& node, const std::string& where, const std::string& key,
                const Eigen::VectorXd& p) {
  for (int i = 0; i < p.size(); ++i) {
    CheckRange(yaml, node, where, key, p[i], -FootstepScenario::kMaxCoordinate, FootstepScenario::kMaxCoordinate,
               " m");
  }
}

FootPose ReadFoot(const YamlReader& yaml, const YAML::Node& node, const std::string& key) {
  const Eigen::VectorXd v = yaml.Numbers(node, key, 3);  // finite: the reader refuses .nan and .inf
  CheckPoint(yaml, node, "the " + key + " foot", key, v.head<2>());
  CheckRange(yaml, node, "the " + key + " foot", key + "'s yaw_deg", v[2], -360.0, 360.0, " degrees");
  FootPose pose;
  pose.x = v[0];
  pose.y = v[1];
  pose.theta = v[2] * kDeg;
  return pose;
}

std::vector<Eigen::Vector2d> ReadPolygon(const YamlReader& yaml, const YAML::Node& region, const std::string& where) {
  std::vector<Eigen::Vector2d> polygon;
  const bool has_box = static_cast<bool>(region["box"]);
  const bool has_polygon = static_cast<bool>(region["polygon"]);
  if (has_box == has_polygon) throw yaml.Error(region, where + " needs exactly one of 'box' or 'polygon'.");
  if (has_box) {
    const YAML::Node box = region["box"];
    yaml.CheckKeys(box, {"min", "max"}, where + "'s box");
    const Eigen::VectorXd lo = yaml.Numbers(yaml.Require(box, "min", where + "'s box"), "min", 2);
    const Eigen::VectorXd hi = yaml.Numbers(yaml.Require(box, "max", where + "'s box"), "max", 2);
    CheckPoint(yaml, box["min"], where + "'s box", "min", lo);
    CheckPoint(yaml, box["max"], where + "'s box", "max", hi);
    if (!(hi[0] > lo[0] && hi[1] > lo[1])) {
      throw yaml.Error(box, where + "'s box must have max > min in x and y, got min [" + Format(lo[0]) + ", " +
                                Format(lo[1]) + "] and max [" + Format(hi[0]) + ", " + Format(hi[1]) + "].");
    }
    polygon = {{lo[0], lo[1]}, {hi[0], lo[1]}, {hi[0], hi[1]}, {lo[0], hi[1]}};
  } else {
    const YAML::Node list = region["polygon"];
    if (!list.IsSequence() || list.size() < 3 || list.size() > FootstepScenario::kMaxPolygonVertices) {
      throw yaml.Error(list, where + "'s polygon must be a list of 3 to " +
                                 cairn::FormatShort(FootstepScenario::kMaxPolygonVertices) + " [x, y] vertices, got " +
                                 (list.IsSequence() ? cairn::FormatShort(list.size()) : std::string("none")) + ".");
    }
    for (const YAML::Node& vertex : list) {
      const Eigen::VectorXd v = yaml.Numbers(vertex, "polygon vertex", 2);
      CheckPoint(yaml, vertex, where + "'s polygon", "vertex", v);
      polygon.emplace_back(v[0], v[1]);
    }
  }
  return polygon;
}

FrictionDistribution ReadFriction(const YamlReader& yaml, const YAML::Node& node, const std::string& where,
                                  std::string* source) {
  try {
    if (node.IsScalar()) {
      const double mu = yaml.AsNumber(node, "friction");
      if (!(mu > 0.0 && mu <= perception::kMaxFrictionCoefficient)) {
        throw yaml.Error(node, where + ": friction must be a coefficient in (0, " +
                                   Format(perception::kMaxFrictionCoefficient) + "], got " + Format(mu) +
                                   "; use {distribution: not_walkable} for ground no foot may use.");
      }
      *source = "mu " + Format(mu);
      return FrictionDistribution::Normal(mu, 0.0);
    }
    yaml.CheckKeys(node, {"distribution", "mean", "stddev", "location", "scale", "shape"}, where + "'s friction");
    const std::string kind = yaml.String(node, "distribution", where + "'s friction", "normal");
    if (kind == "normal" || kind == "truncated_normal") {
      const double mean = yaml.Number(node, "mean", where + "'s friction");
      const double stddev = yaml.Number(node, "stddev", where + "'s friction");
      *source = kind + "(" + Format(mean) + ", " + Format(stddev) + ")";
      const FrictionDistribution distribution = kind == "normal" ? FrictionDistribution::Normal(mean, stddev)
                                                                 : FrictionDistribution::TruncatedNormal(mean, stddev);
      perception::CheckPhysicalFriction(distribution);
      return distribution;
    }
    if (kind == "gev") {
      const double location = yaml.Number(node, "location", where + "'s friction");
      const double scale = yaml.Number(node, "scale", where + "'s friction");
      const double shape = yaml.Number(node, "shape", where + "'s friction");
      *source = "gev(" + Format(location) + ", " + Format(scale) + ", " + Format(shape) + ")";
      const FrictionDistribution distribution = FrictionDistribution::GeneralizedExtremeValue(location, scale, shape);
      perception::CheckPhysicalFriction(distribution);
      return distribution;
    }
    if (kind == "not_walkable") {
      *source = "not walkable";
      return FrictionDistribution::NotWalkable();
    }
    throw yaml.Error(node["distribution"], where + ": unknown friction distribution '" + kind +
                                               "'; use normal, truncated_normal, gev or not_walkable.");
  } catch (const std::invalid_argument& error) {
    const std::string message = error.what();
    if (message.rfind("In '", 0) == 0) throw;
    throw yaml.Error(node, where + ": " + message);
  }
}

}  // namespace

double FootstepScenario::Region::HeightAt(const Eigen::Vector2d& p) const {
  const Eigen::Vector2d u(std::cos(uphill), std::sin(uphill));
  return height + std::tan(slope) * u.dot(p - slope_origin);
}

Eigen::Vector3d FootstepScenario::Region::Normal() const {
  const double t = std::tan(slope);
  return Eigen::Vector3d(-t * std::cos(uphill), -t * std::sin(uphill), 1.0).normalized();
}

bool FootstepScenario::Region::Contains(const Eigen::Vector2d& p) const {
  // Even-odd rule; points on the boundary may fall either way.
  bool inside = false;
  for (std::size_t i = 0, j = polygon.size() - 1; i < polygon.size(); j = i++) {
    const Eigen::Vector2d& a = polygon[i];
    const Eigen::Vector2d& b = polygon[j];
    if ((a.y() > p.y()) != (b.y() > p.y()) && p.x() < (b.x() - a.x()) * (p.y() - a.y()) / (b.y() - a.y()) + a.x()) {
      inside = !inside;
    }
  }
  return inside;
}

FootstepScenario FootstepScenario::Load(const std::string& path) {
  const YamlReader yaml(path, kMaxFileBytes);
  const YAML::Node& root = yaml.root();
  yaml.CheckKeys(root, {"name", "robot", "objective", "oracle", "eta", "materials", "terrain", "obstacles", "start",
                        "goal", "planner"},
                 "the scenario");
  FootstepScenario s;
  s.path_ = path;
  s.name_ = yaml.String(root, "name", "the scenario", path);
  if (root["robot"]) s.robot_ = yaml.Resolve(yaml.AsString(root["robot"], "robot"));
  s.objective_ = yaml.String(root, "objective", "the scenario", s.objective_);
  s.oracle_ = yaml.String(root, "oracle", "the scenario", s.oracle_);
  s.eta_ = yaml.Number(root, "eta", "the scenario", s.eta_);
  if (!(s.eta_ > 0.0 && s.eta_ < 1.0)) {
    throw yaml.Error(root["eta"], "eta must be in (0, 1) (the probability that a foothold's friction is at least "
                                  "what the planner uses), got " + Format(s.eta_) + ".");
  }
  perception::MaterialRegistry& registry = s.registry_;
  if (root["materials"]) {
    registry = perception::MaterialRegistry::LoadYaml(yaml.Resolve(yaml.AsString(root["materials"], "materials")));
  }

  // Terrain.
  const YAML::Node terrain = yaml.Require(root, "terrain", "the scenario");
  yaml.CheckKeys(terrain, {"min", "max", "resolution", "regions"}, "terrain");
  const Eigen::VectorXd lo = yaml.Numbers(yaml.Require(terrain, "min", "terrain"), "min", 2);
  const Eigen::VectorXd hi = yaml.Numbers(yaml.Require(terrain, "max", "terrain"), "max", 2);
  CheckPoint(yaml, terrain["min"], "terrain", "min", lo);
  CheckPoint(yaml, terrain["max"], "terrain", "max", hi);
  if (!(hi[0] > lo[0] && hi[1] > lo[1])) {
    throw yaml.Error(terrain, "terrain 'max' must exceed 'min' in x and y.");
  }
  s.min_corner_ = lo;
  s.max_corner_ = hi;
  s.resolution_ = yaml.Number(terrain, "resolution", "terrain", s.resolution_);
  if (!(s.resolution_ > 0.0 && s.resolution_ <= 0.25)) {
    throw yaml.Error(terrain["resolution"], "terrain resolution must be in (0, 0.25] m so that soles are sampled, got " +
                                                Format(s.resolution_) + ".");
  }
  // The raster is allocated before planning: bound it here, where the line can be named.
  constexpr double kMaxCells = 5e7;
  const double cells = std::ceil((hi[0] - lo[0]) / s.resolution_) * std::ceil((hi[1] - lo[1]) / s.resolution_);
  if (!(cells <= kMaxCells)) {
    throw yaml.Error(terrain, "the terrain needs " + Format(cells) + " cells at resolution " + Format(s.resolution_) +
                                  " m; at most " + Format(kMaxCells) + " are supported. Crop it or coarsen it.");
  }
  const YAML::Node regions = yaml.Require(terrain, "regions", "terrain");
  if (!regions.IsSequence() || regions.size() == 0 || regions.size() > kMaxRegions) {
    throw yaml.Error(regions, "terrain 'regions' must be a list of 1 to " + cairn::FormatShort(kMaxRegions) +
                                  " regions, got " +
                                  (regions.IsSequence() ? cairn::FormatShort(regions.size()) : std::string("none")) + ".");
  }
  for (std::size_t k = 0; k < regions.size(); ++k) {
    const YAML::Node r = regions[k];
    std::string where = "region " + cairn::FormatShort(k + 1);
    if (r.IsMap() && r["name"]) where += " ('" + yaml.AsString(r["name"], "name") + "')";
    yaml.CheckKeys(r, {"name", "box", "polygon", "height", "slope", "friction", "material"}, where);
    Region region;
    region.name = yaml.String(r, "name", where, "region " + cairn::FormatShort(k + 1));
    region.polygon = ReadPolygon(yaml, r, where);
    Eigen::Vector2d box_lo = region.polygon.front(), box_hi = region.polygon.front();
    for (const Eigen::Vector2d& v : region.polygon) {
      box_lo = box_lo.cwiseMin(v);
      box_hi = box_hi.cwiseMax(v);
    }
    if (!(box_hi.x() > lo[0] && box_lo.x() < hi[0] && box_hi.y() > lo[1] && box_lo.y() < hi[1])) {
      throw yaml.Error(r, where + " spans x [" + Format(box_lo.x()) + ", " + Format(box_hi.x()) + "], y [" +
                              Format(box_lo.y()) + ", " + Format(box_hi.y()) + "], wholly outside the terrain's x [" +
                              Format(lo[0]) + ", " + Format(hi[0]) + "], y [" + Format(lo[1]) + ", " +
                              Format(hi[1]) + "]; move it or widen the terrain.");
    }
    region.height = yaml.Number(r, "height", where, 0.0);
    CheckRange(yaml, r["height"] ? r["height"] : r, where, "height", region.height, -kMaxHeight, kMaxHeight, " m");
    if (r["slope"]) {
      const YAML::Node slope = r["slope"];
      yaml.CheckKeys(slope, {"angle_deg", "uphill_deg", "origin"}, where + "'s slope");
      const double angle = yaml.Number(slope, "angle_deg", where + "'s slope");
      if (!(angle >= 0.0 && angle < 80.0)) {
        throw yaml.Error(slope["angle_deg"], where + ": slope angle_deg must be in [0, 80), got " + Format(angle) + ".");
      }
      region.slope = angle * kDeg;
      const double uphill = yaml.Number(slope, "uphill_deg", where + "'s slope", 0.0);
      CheckRange(yaml, slope["uphill_deg"] ? slope["uphill_deg"] : slope, where + "'s slope", "uphill_deg", uphill,
                 -360.0, 360.0, " degrees");
      region.uphill = uphill * kDeg;
      if (slope["origin"]) {
        region.slope_origin = yaml.Numbers(slope["origin"], "origin", 2);
        CheckPoint(yaml, slope["origin"], where + "'s slope", "origin", region.slope_origin);
      }
      // The plane is linear, so its extremes over the polygon are at vertices.
      for (const Eigen::Vector2d& v : region.polygon) {
        const double z = region.HeightAt(v);
        if (!(std::abs(z) <= kMaxHeight)) {
          throw yaml.Error(slope, where + ": the slope puts vertex (" + Format(v.x()) + ", " + Format(v.y()) +
                                      ") at height " + Format(z) + " m, beyond +-" + Format(kMaxHeight) +
                                      " m; lower the angle or move the slope's origin.");
        }
      }
    }
    const bool has_friction = static_cast<bool>(r["friction"]);
    const bool has_material = static_cast<bool>(r["material"]);
    if (has_friction == has_material) {
      throw yaml.Error(r, where + " needs exactly one of 'friction' (a coefficient or a distribution) or 'material' "
                                  "(a label of the material registry).");
    }
    if (has_friction) {
      region.friction = ReadFriction(yaml, r["friction"], where, &region.friction_source);
    } else {
      const std::string label = yaml.AsString(r["material"], "material");
      try {
        region.friction = registry.material(registry.IndexOf(label)).friction;
      } catch (const std::invalid_argument& error) {
        throw yaml.Error(r["material"], where + ": " + error.what());
      }
      region.friction_source = "material " + label;
      region.material = label;
    }
    s.regions_.push_back(std::move(region));
  }

  // Obstacles.
  if (const YAML::Node obstacles = root["obstacles"]) {
    if (!obstacles.IsSequence()) throw yaml.Error(obstacles, "'obstacles' must be a list of boxes.");
    if (obstacles.size() > kMaxObstacles) {
      throw yaml.Error(obstacles, "'obstacles' lists " + cairn::FormatShort(obstacles.size()) + " boxes; at most " +
                                      cairn::FormatShort(kMaxObstacles) +
                                      " are supported (every step is checked against each). Merge neighbouring "
                                      "boxes or mark the ground not walkable instead.");
    }
    for (std::size_t k = 0; k < obstacles.size(); ++k) {
      const YAML::Node o = obstacles[k];
      const std::string where = "obstacle " + cairn::FormatShort(k + 1);
      yaml.CheckKeys(o, {"name", "min", "max", "yaw_deg"}, where);
      TerrainMap::Obstacle obstacle;
      obstacle.name = yaml.String(o, "name", where, where);
      const Eigen::VectorXd omin = yaml.Numbers(yaml.Require(o, "min", where), "min", 3);
      const Eigen::VectorXd omax = yaml.Numbers(yaml.Require(o, "max", where), "max", 3);
      for (const auto& [corner, key] : {std::pair<const Eigen::VectorXd*, const char*>{&omin, "min"}, {&omax, "max"}}) {
        CheckPoint(yaml, o[key], where, key, corner->head<2>());
        CheckRange(yaml, o[key], where, std::string(key) + "'s z", (*corner)[2], -kMaxHeight, kMaxHeight, " m");
      }
      if (!(omax.array() > omin.array()).all()) {
        throw yaml.Error(o, where + " must have max > min on every axis.");
      }
      obstacle.center = 0.5 * (omin + omax);
      obstacle.half_extents = 0.5 * (omax - omin);
      const double yaw = yaml.Number(o, "yaw_deg", where, 0.0);
      CheckRange(yaml, o["yaw_deg"] ? o["yaw_deg"] : o, where, "yaw_deg", yaw, -360.0, 360.0, " degrees");
      obstacle.yaw = yaw * kDeg;
      s.obstacles_.push_back(obstacle);
    }
  }

  // Start and goal.
  const YAML::Node start = yaml.Require(root, "start", "the scenario");
  yaml.CheckKeys(start, {"left", "right"}, "start");
  s.start_.left = ReadFoot(yaml, yaml.Require(start, "left", "start"), "left");
  s.start_.right = ReadFoot(yaml, yaml.Require(start, "right", "start"), "right");
  if (const std::string problem = StanceGeometryProblem(s.start_); !problem.empty()) {
    throw yaml.Error(start, "start: " + problem + ".");
  }
  const YAML::Node goal = yaml.Require(root, "goal", "the scenario");
  yaml.CheckKeys(goal, {"left", "right", "tolerance", "yaw_tolerance_deg"}, "goal");
  s.goal_.stance.left = ReadFoot(yaml, yaml.Require(goal, "left", "goal"), "left");
  s.goal_.stance.right = ReadFoot(yaml, yaml.Require(goal, "right", "goal"), "right");
  if (const std::string problem = StanceGeometryProblem(s.goal_.stance); !problem.empty()) {
    throw yaml.Error(goal, "goal: " + problem + ".");
  }
  s.goal_.position_tolerance = yaml.Number(goal, "tolerance", "goal", s.goal_.position_tolerance);
  const double yaw_tolerance = yaml.Number(goal, "yaw_tolerance_deg", "goal", s.goal_.yaw_tolerance / kDeg);
  CheckRange(yaml, goal["tolerance"] ? goal["tolerance"] : goal, "goal", "tolerance", s.goal_.position_tolerance, 0.0,
             10.0, " m");
  CheckRange(yaml, goal["yaw_tolerance_deg"] ? goal["yaw_tolerance_deg"] : goal, "goal", "yaw_tolerance_deg",
             yaw_tolerance, 0.0, 180.0, " degrees");
  s.goal_.yaw_tolerance = yaw_tolerance * kDeg;

  // Planner settings.
  if (const YAML::Node p = root["planner"]) {
    yaml.CheckKeys(p, {"time_limit", "initial_epsilon", "epsilon_step", "final_epsilon", "max_expansions", "lattice", "orientations",
                       "max_slope_deg", "support_tolerance", "level_step_tolerance"},
                   "planner");
    FootstepPlannerOptions& o = s.planner_;
    o.search.time_limit = yaml.Number(p, "time_limit", "planner", 5.0);
    o.search.initial_epsilon = yaml.Number(p, "initial_epsilon", "planner", o.search.initial_epsilon);
    o.search.epsilon_step = yaml.Number(p, "epsilon_step", "planner", o.search.epsilon_step);
    o.search.final_epsilon = yaml.Number(p, "final_epsilon", "planner", o.search.final_epsilon);
    // Integers are checked as doubles before the cast (NaN, infinity and 1e30 would make it undefined).
    auto integer = [&](const char* key, double fallback, double lo_value, double hi_value) {
      const double v = yaml.Number(p, key, "planner", fallback);
      if (!(v >= lo_value && v <= hi_value) || v != std::floor(v)) {
        throw yaml.Error(p[key], std::string("planner '") + key + "' must be an integer in [" + Format(lo_value) +
                                     ", " + Format(hi_value) + "], got " + Format(v) + ".");
      }
      return v;
    };
    o.search.max_expansions = static_cast<std::int64_t>(integer("max_expansions", -1, -1, 1e15));
    o.lattice_resolution = yaml.Number(p, "lattice", "planner", o.lattice_resolution);
    o.orientations = static_cast<int>(integer("orientations", o.orientations, 1, 32));
    o.max_slope = yaml.Number(p, "max_slope_deg", "planner", o.max_slope / kDeg) * kDeg;
    o.support_tolerance = yaml.Number(p, "support_tolerance", "planner", o.support_tolerance);
    o.level_step_tolerance = yaml.Number(p, "level_step_tolerance", "planner", o.level_step_tolerance);
    auto check = [&](bool ok, const char* key, const std::string& rule) {
      if (!ok) throw yaml.Error(p[key], std::string("planner '") + key + "' " + rule + ".");
    };
    check(o.search.time_limit > 0.0 && o.search.time_limit <= kMaxTimeLimit, "time_limit",
          "must be in (0, " + Format(kMaxTimeLimit) + "] seconds, got " + Format(o.search.time_limit));
    check(o.search.initial_epsilon >= 1.0 && o.search.initial_epsilon <= kMaxEpsilon, "initial_epsilon",
          "must be in [1, " + Format(kMaxEpsilon) + "], got " + Format(o.search.initial_epsilon));
    check(o.search.epsilon_step > 0.0 && o.search.epsilon_step <= kMaxEpsilon, "epsilon_step",
          "must be in (0, " + Format(kMaxEpsilon) + "], got " + Format(o.search.epsilon_step));
    check(o.search.final_epsilon >= 1.0 && o.search.final_epsilon <= o.search.initial_epsilon, "final_epsilon",
          "must be in [1, initial_epsilon]");
    check(o.lattice_resolution >= 0.01 && o.lattice_resolution <= 0.5, "lattice",
          "must be in [0.01, 0.5] m, got " + Format(o.lattice_resolution));
    check(o.max_slope > 0.0 && o.max_slope < M_PI / 2, "max_slope_deg",
          "must be in (0, 90), got " + Format(o.max_slope / kDeg));
    check(o.support_tolerance >= 0.0 && o.support_tolerance <= 1.0, "support_tolerance",
          "must be in [0, 1] m, got " + Format(o.support_tolerance));
    check(o.level_step_tolerance >= 0.0 && o.level_step_tolerance <= 1.0, "level_step_tolerance",
          "must be in [0, 1] m, got " + Format(o.level_step_tolerance));
  } else {
    s.planner_.search.time_limit = 5.0;
  }
  return s;
}

TerrainMap FootstepScenario::BuildTerrain(std::chrono::steady_clock::time_point deadline) const {
  using Clock = std::chrono::steady_clock;
  const Eigen::Vector2d extent = max_corner_ - min_corner_;
  const int cols = static_cast<int>(std::ceil(extent.x() / resolution_ - 1e-9));
  const int rows = static_cast<int>(std::ceil(extent.y() / resolution_ - 1e-9));
  TerrainMap map(min_corner_, cols, rows, resolution_);
  auto check_deadline = [&](const std::string& what) {
    if (deadline != Clock::time_point::max() && Clock::now() >= deadline) {
      throw TimeLimitReached("the time limit ran out while rasterising the terrain of '" + path_ + "' (" + what +
                             ", " + cairn::FormatShort(cols) + " x " + cairn::FormatShort(rows) + " cells)");
    }
  };
  // The chance constraint: the friction each region offers with probability eta. A negative quantile (a wide
  // distribution near zero) means the surface cannot be trusted at that risk: not walkable.
  // Regions are painted in order, each over the cells of its bounding box only, so later regions paint over
  // earlier ones and the work is the regions' area, not cells x regions.
  for (std::size_t k = 0; k < regions_.size(); ++k) {
    const Region& region = regions_[k];
    const double friction = region.friction.walkable() ? std::max(0.0, region.friction.Quantile(1.0 - eta_)) : 0.0;
    const Eigen::Vector3d normal = region.Normal();
    Eigen::Vector2d lo = region.polygon.front(), hi = region.polygon.front();
    for (const Eigen::Vector2d& v : region.polygon) {
      lo = lo.cwiseMin(v);
      hi = hi.cwiseMax(v);
    }
    // Cells whose centre may lie inside: centre c + 0.5 in [lo, hi] / resolution, clamped to the grid.
    auto first = [&](double a, double origin, int n) {
      return static_cast<int>(std::clamp(std::floor((a - origin) / resolution_ - 0.5), 0.0, static_cast<double>(n)));
    };
    auto last = [&](double b, double origin, int n) {
      return static_cast<int>(std::clamp(std::ceil((b - origin) / resolution_ - 0.5), -1.0, static_cast<double>(n - 1)));
    };
    const int c0 = first(lo.x(), min_corner_.x(), cols), c1 = last(hi.x(), min_corner_.x(), cols);
    const int r0 = first(lo.y(), min_corner_.y(), rows), r1 = last(hi.y(), min_corner_.y(), rows);
    for (int row = r0; row <= r1; ++row) {
      check_deadline("region " + cairn::FormatShort(k + 1) + " of " + cairn::FormatShort(regions_.size()));
      for (int col = c0; col <= c1; ++col) {
        const Eigen::Vector2d c = map.CellCenter(col, row);
        if (!region.Contains(c)) continue;
        try {
          map.SetCell(col, row, region.HeightAt(c), normal, friction);
        } catch (const std::exception& error) {
          // Load() bounds every value, so this is a bug; still name the file and the region, not the raster.
          throw std::invalid_argument("In '" + path_ + "': region " + cairn::FormatShort(k + 1) + " ('" + region.name +
                                      "') cannot be placed at (" + Format(c.x()) + ", " + Format(c.y()) +
                                      "): height " + Format(region.HeightAt(c)) + " m, friction " +
                                      Format(friction) + ".");
        }
      }
    }
  }
  for (std::size_t k = 0; k < obstacles_.size(); ++k) {
    check_deadline("obstacle " + cairn::FormatShort(k + 1) + " of " + cairn::FormatShort(obstacles_.size()));
    map.AddObstacle(obstacles_[k]);
  }
  return map;
}

}  // namespace cairn::planning
