#pragma once

/// @file
/// The probing example: seed 001's pipeline as one diagram on a TraverseScenario.

#include <memory>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "cairn/planning/scenarios/traverse_scenario.h"
#include "cairn/systems/framework/diagram.h"

namespace cairn::examples {

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
/// (planning::GridPathPlanner) replans every period; `supervisor` (ProbeSupervisor) chooses and commands probes and
/// pauses `walker` (PathFollower); `arm` (ProbeArm) gives the force that `probe_controller`
/// (perception::ProbeController) turns into C.
std::unique_ptr<systems::Diagram> BuildProbingDiagram(const planning::TraverseScenario& scenario);

/// What a run of the diagram did.
struct ProbingRun {
  Eigen::Vector2d final_position{Eigen::Vector2d::Zero()};
  bool reached_goal{false};
  double time{0.0};
  int probes_made{0};
  /// C of each probe made, in order.
  std::vector<double> collapsibilities;
  /// Positions of the walker at every period.
  std::vector<Eigen::Vector2d> trajectory;
};

/// Builds the diagram and simulates it until the walker is within one cell of the goal or `max_time` s pass.
ProbingRun RunProbingExample(const planning::TraverseScenario& scenario, double max_time);

}  // namespace cairn::examples
