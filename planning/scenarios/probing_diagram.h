#pragma once

/// @file
/// The probing diagram: seed 001's pipeline as one diagram on a TraverseScenario (examples/probing runs it).

#include <memory>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "cairn/perception/terrain/grid_map.h"
#include "cairn/planning/scenarios/traverse_scenario.h"
#include "cairn/planning/scenarios/traverse_simulation.h"
#include "cairn/systems/framework/diagram.h"

namespace cairn::planning {

/// The diagram (subsystems named as below; one period, 0.1 s, for the map, supervisor, planner and walker):
/// ```
///  walker.position ─► sensor ─► mapper ─► analyzer ─► planner ─► walker.path
///        │                        ▲  │                   ▲
///        ├────────────────────────┼──┴─► supervisor ─────┼── pause ─► walker
///        │                probes  └──────────┤  ▲        │
///        │                                   ▼  │ C      │
///        │                                  arm ─► probe_controller
///        └───────────────────────────────────────────────┘ (start)
/// ```
/// `sensor` (ScenarioSensor) feeds `mapper` (perception::ElevationMapper); `analyzer`
/// (perception::TraversabilityAnalyzer) adds the probes' collapsibility and Algorithm 1; `planner`
/// (GridPathPlanner) replans every period; `supervisor` (ProbeSupervisor) chooses and commands probes and
/// pauses `walker` (PathFollower); `arm` (ProbeArm) gives the force that `probe_controller`
/// (perception::ProbeController) turns into C.
/// The arm's force comes from the physics plant (ProbeArmPlant, built from `probe_arm_urdf`) for the scenario's
/// `plant` probe model, from stiffness x depth for `spring`. Without probing (`probing` false) there is no
/// supervisor, arm or probe_controller: the analyzer gets no probes and the walker never pauses. Throws
/// std::invalid_argument as TraverseSimulation::MakeProbeArm does.
std::unique_ptr<systems::Diagram> BuildProbingDiagram(const TraverseScenario& scenario,
                                                      const std::string& probe_arm_urdf, bool probing = true);

/// What a run of the diagram did (the quantities of TraverseSimulation::Result that `cairn traverse` reports).
struct ProbingRun {
  Eigen::Vector2d final_position{Eigen::Vector2d::Zero()};
  bool reached_goal{false};
  /// Why the run stopped early ("" when it reached the goal).
  std::string failure;
  double time{0.0};
  /// Periods (0.1 s) simulated.
  int ticks{0};
  int probes_made{0};
  /// C of each probe made, in order.
  std::vector<double> collapsibilities;
  /// One record per probe made (TraverseSimulation's, with `tick` the period of the probe's command).
  std::vector<TraverseSimulation::ProbeRecord> probes;
  /// Clusters that took a probe's C without a probe of their own (ProbedRegions beyond the probes made).
  int inherited_clusters{0};
  /// The planner's replans (its `status`).
  int replans{0};
  /// Positions of the walker at every period (the start first).
  std::vector<Eigen::Vector2d> trajectory;
  double distance_walked{0.0};
  /// Periods that ended on ground whose true collapsibility is at least 0.5, and the regions entered (in order).
  int collapsible_steps{0};
  std::vector<std::string> regions_entered;
  /// The first plan and the last.
  std::vector<Eigen::Vector2d> first_path;
  std::vector<Eigen::Vector2d> last_path;
  /// The analyzer's map at the end (elevation, slope, roughness, semantic_*, collapsibility, traversability).
  perception::GridMap map{Eigen::Vector2i(1, 1), 1.0, Eigen::Vector2d::Zero()};
  /// Plant time the arm simulated, s (0 with the spring model).
  double probe_simulated_time{0.0};
};

/// Builds the diagram and simulates it with the Simulator until the walker is within one cell of the goal, no path
/// is left, or `max_time` s pass.
ProbingRun RunProbingDiagram(const TraverseScenario& scenario, const std::string& probe_arm_urdf, double max_time,
                             bool probing = true);

}  // namespace cairn::planning
