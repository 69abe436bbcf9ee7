#include "cairn/planning/scenarios/probe_arm.h"

#include <cmath>
#include <stdexcept>
#include <utility>

#include "cairn/common/number_text.h"
#include "cairn/systems/framework/state.h"

namespace cairn::planning {

ProbeArm::ProbeArm(TraverseScenario scenario, std::optional<ProbeArmPlant> arm, double period)
    : scenario_(std::move(scenario)), arm_(std::move(arm)) {
  if (!(period > 0.0) || !std::isfinite(period)) {
    throw std::invalid_argument("ProbeArm: period " + FormatShort(period) + " s must be positive and finite");
  }
  DeclareVectorInputPort("command", 3);
  DeclareVectorInputPort("robot", 2);
  Memory initial;
  initial.rng.seed(static_cast<std::mt19937::result_type>(scenario_.seed));
  memory_state_ = DeclareAbstractState(systems::Value<Memory>(initial));
  const int m = memory_state_;
  const auto playing = [](const Memory& memory) {
    return memory.next >= 1 && memory.next <= static_cast<int>(memory.readings.size());
  };
  DeclareVectorOutputPort(
      "force", 1,
      [m, playing](const systems::Context& c, Eigen::VectorXd* y) {
        const Memory& memory = c.get_abstract_state<Memory>(m);
        (*y)[0] = playing(memory) ? memory.readings[static_cast<std::size_t>(memory.next - 1)] : 0.0;
      },
      {abstract_state_ticket(m)});
  DeclareVectorOutputPort(
      "probing", 1,
      [m, playing](const systems::Context& c, Eigen::VectorXd* y) {
        (*y)[0] = playing(c.get_abstract_state<Memory>(m)) ? 1.0 : 0.0;
      },
      {abstract_state_ticket(m)});
  DeclarePeriodicUnrestrictedUpdateEvent(period, 0.0, &ProbeArm::Update);
}

const ProbeArm::Memory& ProbeArm::memory(const systems::Context& context) const {
  return context.get_abstract_state<Memory>(memory_state_);
}

void ProbeArm::Update(const systems::Context& context, systems::State* next) const {
  Memory& memory = next->get_mutable_abstract_state<Memory>(memory_state_);
  const Eigen::VectorXd& command = get_command_input_port().Eval<Eigen::VectorXd>(context);
  const bool on = command[2] >= 0.5;
  if (on && !memory.commanded) {
    // A new probe: simulate it whole, then play its readings out one per period.
    const Eigen::Vector2d target = command.head<2>();
    memory.readings.clear();
    if (arm_) {
      ProbeArmPlant::Ground ground;
      ground.height = scenario_.HeightAt(target);
      ground.stiffness = scenario_.StiffnessAt(target);
      ground.damping = scenario_.probe_damping;
      const Eigen::Vector2d robot = get_robot_input_port().Eval<Eigen::VectorXd>(context).head<2>();
      const ProbeArmPlant::Probe probe = arm_->Run(robot, target, ground, &memory.rng);
      memory.readings = probe.forces;
      memory.simulated_time += probe.simulated_time;
    } else {
      std::normal_distribution<double> unit(0.0, 1.0);
      const double force = scenario_.StiffnessAt(target) * scenario_.probe_depth;
      for (int k = 0; k < scenario_.probe_samples; ++k) {
        memory.readings.push_back(force + scenario_.force_noise * unit(memory.rng));
      }
    }
    memory.next = 1;
  } else if (on && memory.next >= 1 && memory.next <= static_cast<int>(memory.readings.size())) {
    ++memory.next;
  } else if (!on) {
    memory.next = 0;
  }
  memory.commanded = on;
}

}  // namespace cairn::planning
