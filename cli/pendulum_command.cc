// `cairn pendulum`: runs the systems example (a damped pendulum under discrete PD control) and reports it.

#include <algorithm>
#include <cstdio>
#include <iostream>
#include <memory>
#include <stdexcept>
#include <string>

#include "cairn/common/json_writer.h"
#include "cairn/common/number_text.h"
#include "choice_option.h"
#include "command_registry.h"
#include "examples/systems/pendulum_example.h"
#include "file_checks.h"
#include "numeric_option.h"
#include "usage_error.h"

namespace cairn::cli {
namespace {

// The ranges --help states. A duration or step outside them is no experiment with this pendulum, and their ratio
// is bounded below because steps and log samples grow with it (1e7 steps take seconds; the log keeps a sample
// every 10 ms).
constexpr double kMaxDuration = 1e4;  // s
constexpr double kMinStep = 1e-6;     // s
constexpr double kMaxAngle = 1e3;     // rad
constexpr double kMaxGain = 1e6;
constexpr double kMaxSteps = 1e7;

// The simulator takes at least one step per --max-step and per control period (the ZeroOrderHold's updates).
void CheckStepCount(const examples::PendulumExampleOptions& options) {
  const double steps = options.duration / std::min(options.max_step, options.control_period);
  if (steps > kMaxSteps) {
    throw UsageError("--duration " + FormatShort(options.duration) + " s with steps of at most " +
                     FormatShort(std::min(options.max_step, options.control_period)) + " s needs " +
                     FormatShort(steps) + " integrator steps, more than the limit of " + FormatShort(kMaxSteps) +
                     "; shorten --duration or raise --max-step");
  }
}

}  // namespace

void RegisterPendulumCommand(CommandRegistry* registry) {
  registry->Add("pendulum", "Simulate the example diagram: a damped pendulum under discrete PD control",
                [](CLI::App& app) -> CommandAction {
                  auto options = std::make_shared<examples::PendulumExampleOptions>();
                  auto csv = std::make_shared<std::string>();
                  auto json = std::make_shared<bool>(false);
                  AddNumberOption(app, "--duration", &options->duration, "Simulated time [s]",
                                  NumberRange::AboveAtMost(0.0, kMaxDuration));
                  AddChoiceOption(app, "--integrator", &options->integrator, "Integrator", {"euler", "rk4", "rk45"});
                  AddNumberOption(app, "--max-step", &options->max_step, "Maximum integrator step [s]",
                                  NumberRange::Closed(kMinStep, 1.0));
                  AddNumberOption(app, "--theta0", &options->initial_state[0], "Initial angle [rad]",
                                  NumberRange::Closed(-kMaxAngle, kMaxAngle));
                  AddNumberOption(app, "--target", &options->theta_desired, "Target angle [rad]",
                                  NumberRange::Closed(-kMaxAngle, kMaxAngle));
                  AddNumberOption(app, "--kp", &options->kp, "Proportional gain [N m/rad]",
                                  NumberRange::Closed(0.0, kMaxGain));
                  AddNumberOption(app, "--kd", &options->kd, "Derivative gain [N m s/rad]",
                                  NumberRange::Closed(0.0, kMaxGain));
                  app.add_option("--csv", *csv, "Write the logged state (time, theta, theta_dot) to this CSV file");
                  app.add_flag("--json", *json, "Print one JSON object instead of text");
                  return [options, csv, json]() {
                    CheckStepCount(*options);
                    if (!csv->empty()) CheckOutputFile("--csv", *csv);
                    const examples::PendulumRun run = examples::RunPendulumExample(*options, *csv);
                    if (!run.final_state.allFinite()) {
                      throw std::runtime_error(
                          "the simulation diverged (the state is not finite at t = " + FormatShort(run.final_time) +
                          " s); lower --max-step or the gains" +
                          (options->integrator == "rk45" ? std::string() : std::string(", or use --integrator rk45")));
                    }
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
