#pragma once

/// @file
/// TraverseSimulation: the seed 001 pipeline run on a TraverseScenario — see, map, probe, plan, walk.

#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "cairn/perception/terrain/grid_map.h"
#include "cairn/planning/scenarios/probe_arm_plant.h"
#include "cairn/planning/scenarios/traverse_scenario.h"

namespace cairn::planning {

/// Runs a robot through a TraverseScenario with the seed 001 pipeline, one tick at a time:
///  1. sense: the ground within the sensor's range becomes a point cloud with the D435 noise model and per-point
///     class probabilities, fused into the global map (ElevationFusion, SemanticFusion), then slope, roughness
///     (SlopeRoughnessFilter) and traversability (HierarchicalTraversability, Algorithm 1);
///  2. probe (unless disabled): semantic cells of unknown collapsibility are clustered (ProbingPlanner); a cluster
///     grown out of a probed one inherits its collapsibility; when the nearest candidate is within reach the robot
///     stands still, the probe pushes `probe_depth` into the ground and its force samples are averaged into C
///     (CollapsibilityEstimator, eq. 5), which is fused into the cluster's cells; traversability is recomputed.
///     The force comes from the probe arm in the physics plant (ProbeArmPlant, the scenario's default probe
///     model) or, with the `spring` probe model, from stiffness x depth; both add the sensor's Gaussian noise;
///  3. plan: A* on the traversability (GridSearch), every tick, so the path follows the map's changes; a plan
///     whose previous path the new map blocks counts as a replan;
///  4. walk `step` m along the path.
/// The robot is kinematic (a point; the gait is not the subject). Deterministic for a given seed.
class TraverseSimulation {
 public:
  struct Options {
    /// Probe questionable regions; false reproduces vision-only traversability (the failure the paper prevents).
    bool probing{true};
    /// Threads of the map updates (0 = one per core).
    int num_threads{0};
    /// The probe arm's URDF (data/robots/cairn_probe_arm.urdf), needed by the scenario's plant probe model.
    std::string probe_arm_urdf;
  };

  /// One probe.
  struct ProbeRecord {
    int tick{0};
    Eigen::Vector2d robot{Eigen::Vector2d::Zero()};
    Eigen::Vector2d target{Eigen::Vector2d::Zero()};
    /// "plants" or "water": the cluster's class.
    std::string cluster_class;
    /// The scenario region under the target ("" if none).
    std::string region;
    int cluster_cells{0};
    double average_force{0.0};
    double collapsibility{0.0};
    /// Plant time the probe simulated, s (0 with the spring model).
    double simulated_time{0.0};
    /// Whether the path planned just before the probe crossed the cluster.
    bool path_crossed_cluster{false};
    /// Whether the path planned just after the probe crosses it.
    bool path_crosses_after{false};
  };

  struct Result {
    bool reached_goal{false};
    int ticks{0};
    /// Positions the robot stood on, one per tick it moved (the start first).
    std::vector<Eigen::Vector2d> trajectory;
    double distance_walked{0.0};
    std::vector<ProbeRecord> probes;
    /// Clusters that took a probe's collapsibility without a probe of their own.
    int inherited_clusters{0};
    int replans{0};
    /// Steps onto ground whose true collapsibility is at least 0.5 (soft soil, deep water).
    int collapsible_steps{0};
    /// Names of the scenario regions stepped on, in the order first entered.
    std::vector<std::string> regions_entered;
    /// The first plan, and the last.
    std::vector<Eigen::Vector2d> first_path;
    std::vector<Eigen::Vector2d> last_path;
    /// Why the run stopped early ("" when it reached the goal).
    std::string failure;
    /// The global map at the end: elevation, slope, roughness, semantic_*, collapsibility, traversability.
    perception::GridMap map{Eigen::Vector2i(1, 1), 1.0, Eigen::Vector2d::Zero()};
  };

  /// Throws std::invalid_argument when the scenario's plant probe model has no probe_arm_urdf, the URDF is not
  /// the probe arm, or the scenario's probe (reach, samples) does not fit the arm (naming the value).
  TraverseSimulation(TraverseScenario scenario, const Options& options);

  /// The probe arm of a scenario in the plant: its depth, samples and noise, a 200 Hz force sensor (the hold
  /// lasts samples / 200 Hz, at least 0.1 s). Throws as the constructor does.
  static ProbeArmPlant MakeProbeArm(const TraverseScenario& scenario, const std::string& urdf_path);

  const TraverseScenario& scenario() const { return scenario_; }

  /// Runs the scenario to the goal, to max_ticks, or until no path is left.
  Result Run() const;

 private:
  TraverseScenario scenario_;
  Options options_;
  std::optional<ProbeArmPlant> arm_;
};

}  // namespace cairn::planning
