#include <cairn/planning/walk/walk_run.h>

#include <chrono>
#include <cmath>
#include <stdexcept>

#include <cairn/common/number_text.h>
#include <cairn/multibody/data.h>
#include <cairn/multibody/center_of_mass.h>
#include <cairn/multibody/kinematics.h>
#include <cairn/multibody/plant/sole_state.h>

namespace cairn::planning {

WalkRecord RunWalk(const WalkDiagram& walk, const WalkRunOptions& options) {
  if (!(options.log_period > 0.0 && options.log_period <= 1.0)) {
    throw std::invalid_argument("RunWalk: log_period " + FormatShort(options.log_period) + " s must be in (0, 1]");
  }
  if (!(options.settle_time >= 0.0 && options.settle_time <= 60.0)) {
    throw std::invalid_argument("RunWalk: settle_time " + FormatShort(options.settle_time) + " s must be in [0, 60]");
  }
  if (walk.diagram == nullptr || walk.plan == nullptr || walk.trajectory == nullptr ||
      walk.stabilizer == nullptr || walk.plant == nullptr) {
    throw std::invalid_argument("RunWalk: the walk diagram is empty; build it with BuildWalkDiagram()");
  }
  WalkRecord record;
  systems::Simulator simulator(*walk.diagram);
  record.start = options.initialize ? options.initialize(&simulator) : InitializeWalk(walk, &simulator);
  const systems::Context& root = simulator.get_context();
  record.plan = walk.plan->Eval<FootstepPlan>(walk.diagram->GetSubsystemContext(walk.plan->get_system(), root));
  record.trajectory = walk.trajectory->get_trajectory_output_port().Eval<WholeBodyTrajectory>(
      walk.diagram->GetSubsystemContext(*walk.trajectory, root));
  record.reference = walk.stabilizer->get_reference_output_port().Eval<StabilizedTrajectory>(
      walk.diagram->GetSubsystemContext(*walk.stabilizer, root));
  if (!record.start.ready) return record;

  const multibody::HumanoidPlant& plant = *walk.plant;
  const multibody::Model& robot = plant.model();
  multibody::Data data(robot);
  const auto sample = [&]() {
    const systems::Context& context = walk.diagram->GetSubsystemContext(plant, simulator.get_context());
    const Eigen::VectorXd& x = plant.GetOutputPort("state").Eval<Eigen::VectorXd>(context);
    const auto& soles = plant.GetOutputPort("contacts").Eval<std::vector<multibody::SoleState>>(context);
    const Eigen::VectorXd& energy = plant.GetOutputPort("energy").Eval<Eigen::VectorXd>(context);
    WalkSample s;
    s.time = context.get_time();
    s.q = x.head(robot.nq());
    s.com = multibody::CenterOfMass(robot, data, s.q);
    s.zmp = plant.GetOutputPort("zmp").Eval<Eigen::VectorXd>(context);
    s.left_force = soles[0].normal_force;
    s.right_force = soles[1].normal_force;
    s.left_tangential = soles[0].tangential_force;
    s.right_tangential = soles[1].tangential_force;
    s.com_energy = energy[0];
    s.electrical_energy = energy[1];
    s.heat = energy[2];
    record.samples.push_back(std::move(s));
  };
  const double end = record.reference.duration() + options.settle_time;
  const auto wall = std::chrono::steady_clock::now();
  sample();
  systems::SimulatorStatus status;
  const long long slices = static_cast<long long>(std::ceil(end / options.log_period - 1e-9));
  for (long long k = 1; k <= slices; ++k) {
    status = simulator.AdvanceTo(std::min(end, static_cast<double>(k) * options.log_period));
    sample();
    if (!status.reached_boundary_time()) break;
  }
  record.plant_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall).count();
  if (status.reason == systems::SimulatorStatus::Reason::kEventHandlerFailed) {
    throw std::runtime_error("the walk's simulation failed at t = " + FormatShort(status.time) + " s: " +
                             status.message);
  }
  const systems::Context& context = walk.diagram->GetSubsystemContext(plant, simulator.get_context());
  record.slips = plant.GetOutputPort("slips").Eval<std::vector<multibody::SlipEvent>>(context);
  record.stances = plant.GetOutputPort("stances").Eval<std::vector<multibody::StancePhase>>(context);
  // The plant's own verdict: a fall ends the simulation only when its stop_on_fall option is set.
  const multibody::HumanoidMeasurements& measured = plant.measurements(context);
  record.fell = measured.fallen;
  record.fall_reason = measured.fallen ? measured.fall_reason : "";
  record.duration = context.get_time();
  return record;
}

}  // namespace cairn::planning
