#pragma once

/// @file
/// ProbeSupervisor: the probing planner of seed 001 §5.3 in a diagram — choose, pause, probe, assign, resume.

#include <vector>

#include <Eigen/Core>

#include "cairn/perception/terrain/probed_region.h"
#include "cairn/planning/grid/probing_planner.h"
#include "cairn/systems/framework/leaf_system.h"

namespace cairn::planning {

/// Every `period` seconds: when idle, clusters the map's semantic cells of unknown collapsibility
/// (ProbingPlanner), lets clusters grown out of a probed one inherit its C, and when the nearest
/// candidate is within reach commands the probe there and pauses the robot. While probing it waits
/// `probe_periods` periods for the ProbeController's window, then assigns the measured C to the whole cluster
/// (appending it to `probes`), and resumes.
///
/// | port | type | meaning |
/// |---|---|---|
/// | input `map` | perception::GridMap | TraversabilityAnalyzer's `map` (semantic_*, collapsibility) |
/// | input `robot` | vector of size 2 | the robot's x-y |
/// | input `collapsibility` | vector of size 2 | ProbeController's [C, samples] |
/// | output `probes` | std::vector<perception::ProbedRegion> | every probe and inheritance so far (state) |
/// | output `probe_command` | vector of size 3 | [x, y, active] for the arm (state) |
/// | output `pause` | vector of size 1 | 1 while probing (state) |
///
/// The outputs depend on the state only, so the loop map → supervisor → probes → analyzer → map builds.
class ProbeSupervisor final : public systems::LeafSystem {
 public:
  ProbeSupervisor(const ProbingPlanner::Options& options, double semantic_threshold, int probe_periods,
                  double period);

  const systems::InputPort& get_map_input_port() const { return get_input_port(0); }
  const systems::InputPort& get_robot_input_port() const { return get_input_port(1); }
  const systems::InputPort& get_collapsibility_input_port() const { return get_input_port(2); }
  const systems::OutputPort& get_probes_output_port() const { return get_output_port(0); }
  const systems::OutputPort& get_probe_command_output_port() const { return get_output_port(1); }
  const systems::OutputPort& get_pause_output_port() const { return get_output_port(2); }

  /// The supervisor's state.
  struct Memory {
    ProbingPlanner planner;
    std::vector<perception::ProbedRegion> probes;
    /// Probes actually made (the rest of `probes` are inherited).
    int probes_made{0};
    bool probing{false};
    int periods_left{0};
    Eigen::Vector2d target{Eigen::Vector2d::Zero()};
    ProbingPlanner::Cluster cluster;
    Eigen::Matrix2Xd cluster_points;
  };
  /// The state in `context`.
  const Memory& memory(const systems::Context& context) const;

 private:
  void Update(const systems::Context& context, systems::State* next) const;

  double semantic_threshold_;
  int probe_periods_;
  int memory_state_{};
};

}  // namespace cairn::planning
