#pragma once

#include <chrono>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "cairn/systems/analysis/integrator_base.h"
#include "cairn/systems/framework/context.h"
#include "cairn/systems/framework/event_dispatch.h"
#include "cairn/systems/framework/system.h"

namespace cairn::systems {

/// What a simulator monitor decides after a step.
struct MonitorResult {
  bool stop{false};
  std::string reason;
  static MonitorResult Continue() { return {}; }
  static MonitorResult Stop(std::string why) { return {true, std::move(why)}; }
};

/// Why AdvanceTo() returned.
struct SimulatorStatus {
  /// kReachedTerminationCondition: the monitor stopped the run, or an event handler returned
  /// EventStatus::ReachedTermination; kEventHandlerFailed: a handler returned EventStatus::Failed (the updates of
  /// that step were not applied). `message` then says why, prefixed with the handler's system path.
  enum class Reason { kReachedBoundaryTime, kReachedTerminationCondition, kEventHandlerFailed };
  Reason reason{Reason::kReachedBoundaryTime};
  double time{0.0};
  std::string message;
  bool reached_boundary_time() const { return reason == Reason::kReachedBoundaryTime; }
};

/// Advances a system's context through time: events and continuous integration.
///
/// Each step: (1) unrestricted, then discrete updates due at the current time (periodic ones due now, and
/// per-step ones); (2) integration of the continuous state to the next periodic event time or the boundary,
/// whichever is first (several integrator steps for fixed-step integrators); (3) publishes due at the new time;
/// (4) the monitor. Initialize() runs initialization events and the publishes due at the initial time. Periodic
/// events land exactly on offset + k * period. An event handler that returns EventStatus::ReachedTermination or
/// EventStatus::Failed ends AdvanceTo() after its group of events, which returns the status with its message.
///
/// The default integrator is RK4 with a 1 ms maximum step.
///
/// Every AdvanceTo() is bounded by a step limit (kDefaultStepLimit unless set_step_limit() says otherwise): a
/// run that needs more steps than the limit, judged before it starts from the maximum step size and the event
/// periods, is refused with std::invalid_argument, and one that reaches the limit anyway (an error-controlled
/// integrator taking small steps) stops with std::runtime_error. So a tiny step or a huge end time is an error
/// message, not a run that never finishes.
class Simulator {
 public:
  /// Steps one AdvanceTo() may take unless set_step_limit() says otherwise: 100 million (minutes of a small
  /// diagram; hours of a large one).
  static constexpr int64_t kDefaultStepLimit = 100'000'000;

  /// Simulates `system` from `context` (default: a new default context). The system must outlive the simulator.
  explicit Simulator(const System& system, std::unique_ptr<Context> context = nullptr);
  ~Simulator();

  /// Runs initialization events; called by AdvanceTo() if not called before.
  void Initialize();
  /// Advances to time `t_final` (finite, >= current time), or until the monitor stops the run. Throws
  /// std::invalid_argument before running if reaching t_final needs more than step_limit() steps (at least
  /// (t_final - t) / h with continuous state and maximum step h, and (t_final - t) / period for each periodic
  /// event), or if an event period is below the time resolution at t_final (period <= 1e-12 |t_final|, the
  /// relative tolerance at which event times coincide); throws std::runtime_error if the run reaches the step
  /// limit anyway.
  SimulatorStatus AdvanceTo(double t_final);

  /// Most steps one AdvanceTo() may take; throws std::invalid_argument unless `steps` >= 1.
  void set_step_limit(int64_t steps);
  int64_t step_limit() const { return step_limit_; }

  /// Replaces the integrator (e.g. RungeKutta45Integrator). Returns a reference to it.
  template <class I, typename... Args>
  I& ResetIntegrator(Args&&... args) {
    auto integrator = std::make_unique<I>(std::forward<Args>(args)...);
    I& reference = *integrator;
    integrator_ = std::move(integrator);
    return reference;
  }
  IntegratorBase& get_mutable_integrator() { return *integrator_; }
  const IntegratorBase& get_integrator() const { return *integrator_; }

  /// Paces the simulation to `rate` x real time (0 = as fast as possible).
  void set_target_realtime_rate(double rate);
  /// Called after initialization and after every step; returning MonitorResult::Stop ends AdvanceTo().
  void set_monitor(std::function<MonitorResult(const Context&)> monitor) { monitor_ = std::move(monitor); }

  const Context& get_context() const { return *context_; }
  /// Mutable access to the context; changing it after Initialize() is allowed (e.g. to perturb the state).
  Context& get_mutable_context() { return *context_; }
  const System& get_system() const { return system_; }

  int64_t num_steps_taken() const { return num_steps_; }
  int64_t num_discrete_updates() const { return num_discrete_updates_; }
  int64_t num_unrestricted_updates() const { return num_unrestricted_updates_; }
  int64_t num_publishes() const { return num_publishes_; }

 private:
  // Periodic events due at the earliest time after (or, inclusive, at) `time`.
  double NextPeriodicEvents(double time, bool inclusive, std::vector<internal::TriggeredEvent>* due) const;
  EventStatus ApplyUpdates(const std::vector<internal::TriggeredEvent>& timed);
  EventStatus Publish(const std::vector<internal::TriggeredEvent>& timed);
  // Fills `status` and returns true if `event_status` stops the run.
  bool StopsRun(const EventStatus& event_status, SimulatorStatus* status) const;
  bool CallMonitor(SimulatorStatus* status);
  void PaceRealTime();
  void CheckStepBudget(double t_final);

  const System& system_;
  std::unique_ptr<Context> context_;
  std::unique_ptr<IntegratorBase> integrator_;
  std::function<MonitorResult(const Context&)> monitor_;
  double realtime_rate_{0.0};
  bool initialized_{false};
  int64_t step_limit_{kDefaultStepLimit};

  std::vector<LeafAndContext> leaves_;
  std::vector<internal::TriggeredEvent> per_step_updates_;
  std::vector<internal::TriggeredEvent> per_step_publishes_;
  std::vector<internal::TriggeredEvent> pending_updates_;  // Periodic updates due at the current time.
  EventStatus initialization_status_ = EventStatus::DidNothing();  // What Initialize()'s events reported.

  std::chrono::steady_clock::time_point wall_start_;
  double sim_start_{0.0};
  int64_t num_steps_{0};
  int64_t num_discrete_updates_{0};
  int64_t num_unrestricted_updates_{0};
  int64_t num_publishes_{0};
};

}  // namespace cairn::systems
