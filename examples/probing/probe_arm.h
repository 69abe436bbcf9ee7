#pragma once

/// @file
/// ProbeArm: the probing arm's tip force on a TraverseScenario's ground, as a system.

#include "cairn/planning/scenarios/traverse_scenario.h"
#include "cairn/systems/framework/leaf_system.h"

namespace cairn::examples {

/// While commanded, the arm pushes the scenario's probe depth into the ground at the commanded point; the force is
/// the ground's stiffness there times the depth (a linear spring per region: soft soil, deep water with none,
/// hard ground), noise-free. Not the physics plant: a stand-in with the same ports a simulated 2-DoF arm with a
/// force sensor would have.
///
/// | port | type | meaning |
/// |---|---|---|
/// | input `command` | vector of size 3 | [x, y, active (>= 0.5)] (ProbeSupervisor's `probe_command`) |
/// | output `force` | vector of size 1 | N (0 when not probing) |
/// | output `probing` | vector of size 1 | 1 while probing |
class ProbeArm final : public systems::LeafSystem {
 public:
  explicit ProbeArm(planning::TraverseScenario scenario);

  const systems::InputPort& get_command_input_port() const { return get_input_port(0); }

 private:
  planning::TraverseScenario scenario_;
};

}  // namespace cairn::examples
