// `cairn pendulum`: runs the systems example (a damped pendulum under discrete PD control) and reports it.

#include <cstdio>
#include <iostream>
#include <memory>
#include <string>

#include "cairn/common/json_writer.h"
#include "command_registry.h"
#include "examples/systems/pendulum_example.h"

namespace cairn::cli {

void RegisterPendulumCommand(CommandRegistry* registry) {
  registry->Add("pendulum", "Simulate the example diagram: a damped pendulum under discrete PD control",
                [](CLI::App& app) -> CommandAction {
                  auto options = std::make_shared<examples::PendulumExampleOptions>();
                  auto csv = std::make_shared<std::string>();
                  auto json = std::make_shared<bool>(false);
                  app.add_option("--duration", options->duration, "Simulated time [s]")
                      ->check(CLI::PositiveNumber)
                      ->capture_default_str();
                  app.add_option("--integrator", options->integrator, "Integrator")
                      ->check(CLI::IsMember({"euler", "rk4", "rk45"}))
                      ->capture_default_str();
                  app.add_option("--max-step", options->max_step, "Maximum integrator step [s]")
                      ->check(CLI::PositiveNumber)
                      ->capture_default_str();
                  app.add_option("--theta0", options->initial_state[0], "Initial angle [rad]")->capture_default_str();
                  app.add_option("--target", options->theta_desired, "Target angle [rad]")->capture_default_str();
                  app.add_option("--kp", options->kp, "Proportional gain [N m/rad]")
                      ->check(CLI::NonNegativeNumber)
                      ->capture_default_str();
                  app.add_option("--kd", options->kd, "Derivative gain [N m s/rad]")
                      ->check(CLI::NonNegativeNumber)
                      ->capture_default_str();
                  app.add_option("--csv", *csv, "Write the logged state (time, theta, theta_dot) to this CSV file");
                  app.add_flag("--json", *json, "Print one JSON object instead of text");
                  return [options, csv, json]() {
                    const examples::PendulumRun run = examples::RunPendulumExample(*options, *csv);
                    char line[512];
                    if (*json) {
                      const JsonWriter::NumberFormat f9 = JsonWriter::Fixed(9);
                      JsonWriter out;
                      out.BeginObject().Key("time").Number(run.final_time, JsonWriter::Fixed(6));
                      out.Key("theta").Number(run.final_state[0], f9).Key("theta_dot").Number(run.final_state[1], f9);
                      out.Key("predicted_equilibrium").Number(run.predicted_equilibrium, f9);
                      out.Key("energy_J").Number(run.final_energy, f9).Key("steps").Integer(run.steps);
                      out.Key("log_samples").Integer(run.log_times.size()).EndObject();
                      std::cout << out.text() << "\n";
                      return 0;
                    }
                    std::snprintf(line, sizeof(line),
                                  "Pendulum (m = %.3g kg, l = %.3g m, b = %.3g N m s) under PD control "
                                  "(kp = %.3g, kd = %.3g) sampled every %.3g s by a ZeroOrderHold; %s, %.3g s.\n",
                                  options->plant.mass, options->plant.length, options->plant.damping, options->kp,
                                  options->kd, options->control_period, options->integrator.c_str(),
                                  options->duration);
                    std::cout << line;
                    std::snprintf(line, sizeof(line),
                                  "  start:  theta = %.4f rad, target %.4f rad\n"
                                  "  final:  theta = %.6f rad, theta_dot = %.2e rad/s at t = %.3f s (%lld steps)\n"
                                  "  theory: PD equilibrium kp (target - theta) = m g l sin(theta) at theta = %.6f "
                                  "rad\n",
                                  options->initial_state[0], options->theta_desired, run.final_state[0],
                                  run.final_state[1], run.final_time, static_cast<long long>(run.steps),
                                  run.predicted_equilibrium);
                    std::cout << line;
                    std::cout << "  log:    " << run.log_times.size() << " samples"
                              << (csv->empty() ? std::string(" (write them with --csv FILE)")
                                               : " written to " + *csv)
                              << "\n";
                    return 0;
                  };
                });
}

}  // namespace cairn::cli
