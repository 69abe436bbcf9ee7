#include "examples/systems/pendulum_example.h"

#include <cmath>
#include <stdexcept>

#include "cairn/common/number_text.h"
#include "cairn/systems/analysis/explicit_euler_integrator.h"
#include "cairn/systems/analysis/runge_kutta45_integrator.h"
#include "cairn/systems/analysis/runge_kutta4_integrator.h"
#include "cairn/systems/analysis/simulator.h"
#include "cairn/systems/framework/diagram_builder.h"
#include "cairn/systems/primitives/vector_log_sink.h"
#include "cairn/systems/primitives/zero_order_hold.h"
#include "examples/systems/pd_controller.h"

namespace cairn::examples {

using systems::DiagramBuilder;

std::unique_ptr<systems::Diagram> BuildPendulumDiagram(const PendulumExampleOptions& options) {
  DiagramBuilder builder;
  auto* plant = builder.AddNamedSystem<PendulumPlant>("plant", options.plant);
  auto* hold = builder.AddNamedSystem<systems::ZeroOrderHold>("hold", options.control_period, 2);
  auto* controller = builder.AddNamedSystem<PdController>("controller", options.kp, options.kd, options.theta_desired);
  builder.Connect(plant->GetOutputPort("state"), hold->get_input_port());
  builder.Connect(hold->get_output_port(), controller->get_input_port());
  builder.Connect(controller->get_output_port(), plant->get_input_port());
  auto* logger = LogVectorOutput(plant->GetOutputPort("state"), &builder, options.log_period);
  logger->set_name("logger");
  auto diagram = builder.Build();
  diagram->set_name("pendulum");
  return diagram;
}

namespace {

// Solves kp (θd − θ) = m g l sin θ by Newton's method from θd (the left side falls, the right rises, near θd).
double PredictEquilibrium(const PendulumExampleOptions& o) {
  const double mgl = o.plant.mass * o.plant.gravity * o.plant.length;
  double theta = o.theta_desired;
  for (int i = 0; i < 50; ++i) {
    const double residual = o.kp * (o.theta_desired - theta) - mgl * std::sin(theta);
    const double slope = -o.kp - mgl * std::cos(theta);
    theta -= residual / slope;
  }
  return theta;
}

}  // namespace

PendulumRun RunPendulumExample(const PendulumExampleOptions& options, const std::string& csv_path) {
  if (!(options.duration > 0.0) || !std::isfinite(options.duration)) {
    throw std::invalid_argument("The duration must be finite and > 0 s; got " + cairn::FormatShort(options.duration) + ".");
  }
  auto diagram = BuildPendulumDiagram(options);
  const auto& plant = static_cast<const PendulumPlant&>(diagram->GetSubsystemByName("plant"));
  const auto& logger = static_cast<const systems::VectorLogSink&>(diagram->GetSubsystemByName("logger"));

  systems::Simulator simulator(*diagram);
  if (options.integrator == "euler") {
    simulator.ResetIntegrator<systems::ExplicitEulerIntegrator>(options.max_step);
  } else if (options.integrator == "rk4") {
    simulator.ResetIntegrator<systems::RungeKutta4Integrator>(options.max_step);
  } else if (options.integrator == "rk45") {
    simulator.ResetIntegrator<systems::RungeKutta45Integrator>(options.max_step, options.accuracy);
  } else {
    throw std::invalid_argument("Unknown integrator '" + options.integrator + "'; use euler, rk4 or rk45.");
  }
  systems::Context& plant_context = diagram->GetMutableSubsystemContext(plant, &simulator.get_mutable_context());
  plant_context.SetContinuousState(options.initial_state);
  simulator.AdvanceTo(options.duration);

  PendulumRun run;
  run.final_state = plant_context.get_continuous_state_vector();
  run.final_time = simulator.get_context().get_time();
  run.final_energy = plant.CalcTotalEnergy(plant_context);
  run.predicted_equilibrium = PredictEquilibrium(options);
  run.steps = simulator.num_steps_taken();
  const auto& log = logger.GetLog(diagram->GetSubsystemContext(logger, simulator.get_context()));
  run.log_times = log.sample_times();
  run.log_states = log.data();
  if (!csv_path.empty()) log.WriteCsv(csv_path, {"theta", "theta_dot"});
  return run;
}

}  // namespace cairn::examples
