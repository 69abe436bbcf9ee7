#include "examples/probing/probe_arm.h"

namespace cairn::examples {

ProbeArm::ProbeArm(planning::TraverseScenario scenario) : scenario_(std::move(scenario)) {
  DeclareVectorInputPort("command", 3);
  DeclareVectorOutputPort("force", 1, [this](const systems::Context& c, Eigen::VectorXd* y) {
    const Eigen::VectorXd& command = get_command_input_port().Eval<Eigen::VectorXd>(c);
    (*y)[0] = command[2] >= 0.5 ? scenario_.StiffnessAt(command.head<2>()) * scenario_.probe_depth : 0.0;
  });
  DeclareVectorOutputPort("probing", 1, [this](const systems::Context& c, Eigen::VectorXd* y) {
    (*y)[0] = get_command_input_port().Eval<Eigen::VectorXd>(c)[2] >= 0.5 ? 1.0 : 0.0;
  });
}

}  // namespace cairn::examples
