#pragma once

#include <chrono>
#include <cstddef>
#include <string>
#include <vector>

#include <Eigen/Core>

#include <cairn/perception/friction/friction_distribution.h>
#include <cairn/perception/friction/material_registry.h>
#include <cairn/planning/footstep/foot_pose.h>
#include <cairn/planning/footstep/footstep_planner_options.h>
#include <cairn/planning/footstep/terrain_map.h>

namespace cairn::planning {

/// A footstep planning problem read from YAML (schema: docs/scenarios.md): terrain regions with heights, slopes
/// and friction distributions, box obstacles, start and goal stances, the robot, the objective and the oracle's
/// source, η and the planner's settings. Errors name the file, the line and the key.
class FootstepScenario {
 public:
  /// A patch of ground: a polygon (a box is a 4-gon) carrying a plane and a friction distribution.
  struct Region {
    std::string name;
    std::vector<Eigen::Vector2d> polygon;  ///< counter-clockwise or clockwise, at least 3 vertices
    double height{0.0};                    ///< at `slope_origin`, m
    double slope{0.0};                     ///< rad
    double uphill{0.0};                    ///< direction of steepest ascent, rad from the x axis
    Eigen::Vector2d slope_origin{Eigen::Vector2d::Zero()};
    perception::FrictionDistribution friction{perception::FrictionDistribution::Normal(1.0, 0.0)};
    std::string friction_source;  ///< "mu 0.12", "material asphalt", "normal(0.5, 0.1)", for reports
    std::string material;         ///< the registry label of a `material:` region (what it looks like); else empty

    /// Ground height of the region's plane at (x, y).
    double HeightAt(const Eigen::Vector2d& p) const;
    Eigen::Vector3d Normal() const;
    bool Contains(const Eigen::Vector2d& p) const;
  };

  /// What a scenario file may state, checked before anything is built from it: regions (1000) and obstacles
  /// (1000: every candidate step is checked against each obstacle, and the heuristic's precomputation against
  /// each for every lattice link), polygon vertices (1000), heights of ground and obstacles (+-100 m), horizontal
  /// coordinates (+-1e4 m), the planner's time limit (1e6 s) and its epsilons (100). Friction coefficients lie
  /// in (0, perception::kMaxFrictionCoefficient] (perception::CheckPhysicalFriction() for distributions).
  static constexpr std::size_t kMaxRegions = 1000;
  /// See kMaxRegions.
  static constexpr std::size_t kMaxObstacles = 1000;
  /// See kMaxRegions.
  static constexpr std::size_t kMaxPolygonVertices = 1000;
  /// See kMaxRegions.
  static constexpr double kMaxHeight = 100.0;
  /// See kMaxRegions.
  static constexpr double kMaxCoordinate = 1e4;
  /// See kMaxRegions.
  static constexpr double kMaxTimeLimit = 1e6;
  /// See kMaxRegions.
  static constexpr double kMaxEpsilon = 100.0;
  /// Largest scenario file (2 MiB), refused from its size before it is parsed: the count limits above admit
  /// files of a few hundred kilobytes (1000 box regions and 1000 obstacles take about 100 KB), and parsing takes
  /// time and memory in proportion to the file (4 MB of obstacles took 3 s and 590 MB before they were counted).
  static constexpr std::size_t kMaxFileBytes = 2u << 20;

  /// Reads and validates a scenario; throws std::invalid_argument naming the file, the line and the key for a
  /// missing, unknown, mistyped or out-of-range value (the limits above, NaN or infinity anywhere), a region
  /// wholly outside the terrain, or a start or goal stance that cannot stand (StanceGeometryProblem()).
  static FootstepScenario Load(const std::string& path);

  const std::string& path() const { return path_; }
  const std::string& name() const { return name_; }
  /// The robot's walking-model YAML, resolved against the scenario's folder; empty for the default robot.
  const std::string& robot() const { return robot_; }
  /// "ecom", "ecom_heat", "time" or "torque" (checked by the caller that owns the objectives).
  const std::string& objective() const { return objective_; }
  /// Where the transition oracle's step costs come from: "model" (the default), "plant" or "pipeline" (checked by
  /// the caller that owns the sources, as the objective); a command's --oracle-source overrides it.
  const std::string& oracle() const { return oracle_; }
  double eta() const { return eta_; }
  const std::vector<Region>& regions() const { return regions_; }
  /// The material registry `material:` regions were read with (`materials:`, default thesis Table 3.3): what a
  /// perception pipeline seeing this scenario believes about its materials.
  const perception::MaterialRegistry& registry() const { return registry_; }
  /// The mapped area's corners, [x, y].
  const Eigen::Vector2d& min_corner() const { return min_corner_; }
  const Eigen::Vector2d& max_corner() const { return max_corner_; }
  /// The raster's cell size, m.
  double resolution() const { return resolution_; }
  const std::vector<TerrainMap::Obstacle>& obstacles() const { return obstacles_; }
  const Stance& start() const { return start_; }
  const StanceGoal& goal() const { return goal_; }
  const FootstepPlannerOptions& planner() const { return planner_; }
  FootstepPlannerOptions& mutable_planner() { return planner_; }
  void set_objective(const std::string& objective) { objective_ = objective; }

  /// Rasterises the regions (later regions paint over earlier ones) and obstacles. A cell's friction is the
  /// (1 - eta) quantile of its region's distribution, the chance constraint of thesis eq. 5.3. Throws
  /// TimeLimitReached (naming the file and how far it got) if the work is still running at `deadline`, so that
  /// a planning time limit can cover the set-up before the search too.
  TerrainMap BuildTerrain(
      std::chrono::steady_clock::time_point deadline = std::chrono::steady_clock::time_point::max()) const;

 private:
  std::string path_;
  std::string name_;
  std::string robot_;
  std::string objective_{"ecom_heat"};
  std::string oracle_{"model"};
  double eta_{0.95};
  Eigen::Vector2d min_corner_{Eigen::Vector2d::Zero()};
  Eigen::Vector2d max_corner_{Eigen::Vector2d::Zero()};
  double resolution_{0.025};
  std::vector<Region> regions_;
  perception::MaterialRegistry registry_{perception::MaterialRegistry::ThesisTable33()};
  std::vector<TerrainMap::Obstacle> obstacles_;
  Stance start_;
  StanceGoal goal_;
  FootstepPlannerOptions planner_;
};

}  // namespace cairn::planning
