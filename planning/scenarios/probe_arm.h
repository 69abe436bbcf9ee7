#pragma once

/// @file
/// ProbeArm: the probing arm's tip force on a TraverseScenario's ground, as a system.

#include <optional>
#include <random>
#include <vector>

#include "cairn/planning/scenarios/probe_arm_plant.h"
#include "cairn/planning/scenarios/traverse_scenario.h"
#include "cairn/systems/framework/leaf_system.h"

namespace cairn::planning {

/// Every `period` seconds (the force sensor's period): when the command switches on, the arm probes the
/// commanded point from the robot's position. With a ProbeArmPlant (the scenario's `plant` probe model) the
/// whole probe is simulated in the physics plant in that event and its readings (with the sensor's seeded noise)
/// are played out one per period; with the `spring` model the readings are stiffness x depth plus the same noise.
/// After the last reading `probing` drops to 0 until the command switches off and on again.
///
/// | port | type | meaning |
/// |---|---|---|
/// | input `command` | vector of size 3 | [x, y, active (>= 0.5)] (ProbeSupervisor's `probe_command`) |
/// | input `robot` | vector of size 2 | the robot's x-y (the arm's base) |
/// | output `force` | vector of size 1 | the current reading, N (0 when not probing) |
/// | output `probing` | vector of size 1 | 1 while readings are played out |
///
/// State (abstract): the readings of the current probe, the next one's index, whether the command was on, and
/// the noise generator. The outputs depend on the state only.
class ProbeArm final : public systems::LeafSystem {
 public:
  /// `arm` is the plant model (none: the spring model). Throws std::invalid_argument for a non-positive or
  /// non-finite period.
  ProbeArm(TraverseScenario scenario, std::optional<ProbeArmPlant> arm, double period);

  const systems::InputPort& get_command_input_port() const { return get_input_port(0); }
  const systems::InputPort& get_robot_input_port() const { return get_input_port(1); }
  const systems::OutputPort& get_force_output_port() const { return get_output_port(0); }
  const systems::OutputPort& get_probing_output_port() const { return get_output_port(1); }

  struct Memory {
    std::vector<double> readings;
    int next{0};
    bool commanded{false};
    /// Plant time simulated by all probes so far, s.
    double simulated_time{0.0};
    std::mt19937 rng;
  };
  const Memory& memory(const systems::Context& context) const;

 private:
  void Update(const systems::Context& context, systems::State* next) const;

  TraverseScenario scenario_;
  std::optional<ProbeArmPlant> arm_;
  int memory_state_{};
};

}  // namespace cairn::planning
