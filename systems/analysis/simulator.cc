#include "cairn/systems/analysis/simulator.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <thread>
#include <utility>

#include "cairn/common/number_text.h"
#include "cairn/systems/analysis/runge_kutta4_integrator.h"
#include "cairn/systems/framework/leaf_system.h"

namespace cairn::systems {
namespace {

// Times closer than this (relative) are the same event time: periodic events with different periods that
// coincide in exact arithmetic may differ in the last bits.
bool SameTime(double a, double b) {
  if (std::isinf(a) || std::isinf(b)) return a == b;
  return std::abs(a - b) <= 1e-12 * std::max(1.0, std::abs(b));
}

// The first time offset + k * period (k >= 0) that is after `time` (or at it, if inclusive). Computed from k, so
// repeated calls give bit-identical times and the simulator lands exactly on them.
double NextOccurrence(const PeriodicEventData& timing, double time, bool inclusive) {
  if (time < timing.offset || (inclusive && SameTime(time, timing.offset))) {
    return timing.offset;
  }
  // In exact arithmetic k0 or k0 + 1 is the answer; rounding may need one more. A period so small against
  // `time` that none of these is later would make k + 1 == k, so the search is bounded and reports that.
  const double k0 = std::floor((time - timing.offset) / timing.period);
  for (int i = 0; i < 4; ++i) {
    const double candidate = timing.offset + (k0 + i) * timing.period;
    if (SameTime(candidate, time)) {
      if (inclusive) return candidate;
      continue;
    }
    if (candidate > time) return candidate;
  }
  throw std::runtime_error("A periodic event with period " + FormatShort(timing.period) +
                           " s cannot be told apart from the next at t = " + FormatShort(time) +
                           " (event times closer than 1e-12 relative coincide); use a longer period or start "
                           "nearer t = 0.");
}

void Split(const std::vector<internal::TriggeredEvent>& events, EventKind kind,
           std::vector<internal::TriggeredEvent>* out) {
  for (const auto& event : events) {
    if (event.event->kind == kind) out->push_back(event);
  }
}

}  // namespace

Simulator::Simulator(const System& system, std::unique_ptr<Context> context)
    : system_(system),
      context_(context ? std::move(context) : system.CreateDefaultContext()),
      integrator_(std::make_unique<RungeKutta4Integrator>(1e-3)) {
  system_.ValidateContext(*context_);
  if (!context_->is_root()) {
    throw std::invalid_argument("Simulator needs a root context; this one belongs to a subsystem of a diagram.");
  }
}

Simulator::~Simulator() = default;

void Simulator::set_target_realtime_rate(double rate) {
  if (!(rate >= 0.0) || !std::isfinite(rate)) {
    throw std::invalid_argument("The target real-time rate must be finite and >= 0 (0 = as fast as possible); got " +
                                FormatShort(rate) + ".");
  }
  realtime_rate_ = rate;
  wall_start_ = std::chrono::steady_clock::now();
  sim_start_ = context_->get_time();
}

double Simulator::NextPeriodicEvents(double time, bool inclusive, std::vector<internal::TriggeredEvent>* due) const {
  double earliest = std::numeric_limits<double>::infinity();
  due->clear();
  for (const LeafAndContext& leaf : leaves_) {
    for (const Event& event : leaf.system->declared_events()) {
      if (event.trigger != TriggerType::kPeriodic) continue;
      const double t = NextOccurrence(event.periodic, time, inclusive);
      if (t < earliest && !SameTime(t, earliest)) {
        earliest = t;
        due->clear();
      }
      if (SameTime(t, earliest)) due->push_back({leaf.system, leaf.context, &event});
    }
  }
  return earliest;
}

EventStatus Simulator::ApplyUpdates(const std::vector<internal::TriggeredEvent>& timed) {
  std::vector<internal::TriggeredEvent> events;
  Split(timed, EventKind::kUnrestrictedUpdate, &events);
  Split(per_step_updates_, EventKind::kUnrestrictedUpdate, &events);
  EventStatus status = internal::ApplyUnrestrictedUpdates(events);
  num_unrestricted_updates_ += static_cast<int64_t>(events.size());
  if (status.failed()) return status;
  events.clear();
  Split(timed, EventKind::kDiscreteUpdate, &events);
  Split(per_step_updates_, EventKind::kDiscreteUpdate, &events);
  status.KeepMoreSevere(internal::ApplyDiscreteUpdates(events));
  num_discrete_updates_ += static_cast<int64_t>(events.size());
  return status;
}

EventStatus Simulator::Publish(const std::vector<internal::TriggeredEvent>& timed) {
  std::vector<internal::TriggeredEvent> events;
  Split(timed, EventKind::kPublish, &events);
  events.insert(events.end(), per_step_publishes_.begin(), per_step_publishes_.end());
  num_publishes_ += static_cast<int64_t>(events.size());
  return internal::DispatchPublishes(events);
}

bool Simulator::StopsRun(const EventStatus& event_status, SimulatorStatus* status) const {
  if (!event_status.stops()) return false;
  status->reason = event_status.failed() ? SimulatorStatus::Reason::kEventHandlerFailed
                                         : SimulatorStatus::Reason::kReachedTerminationCondition;
  status->time = context_->get_time();
  status->message = event_status.message();
  return true;
}

bool Simulator::CallMonitor(SimulatorStatus* status) {
  if (!monitor_) return false;
  MonitorResult result = monitor_(*context_);
  if (!result.stop) return false;
  status->reason = SimulatorStatus::Reason::kReachedTerminationCondition;
  status->time = context_->get_time();
  status->message = std::move(result.reason);
  return true;
}

void Simulator::Initialize() {
  leaves_ = system_.CollectLeafSystems(context_.get());
  per_step_updates_.clear();
  per_step_publishes_.clear();
  internal::CollectEvents(leaves_, TriggerType::kPerStep, EventKind::kUnrestrictedUpdate, &per_step_updates_);
  internal::CollectEvents(leaves_, TriggerType::kPerStep, EventKind::kDiscreteUpdate, &per_step_updates_);
  internal::CollectEvents(leaves_, TriggerType::kPerStep, EventKind::kPublish, &per_step_publishes_);

  initialization_status_ = internal::ExecuteAll(leaves_, TriggerType::kInitialization);

  // Periodic events due exactly now: their updates open the first step, their publishes happen now.
  std::vector<internal::TriggeredEvent> due;
  const double t0 = context_->get_time();
  const double first = NextPeriodicEvents(t0, /*inclusive=*/true, &due);
  pending_updates_.clear();
  if (SameTime(first, t0)) {
    Split(due, EventKind::kUnrestrictedUpdate, &pending_updates_);
    Split(due, EventKind::kDiscreteUpdate, &pending_updates_);
  } else {
    due.clear();
  }
  initialization_status_.KeepMoreSevere(Publish(due));
  initialized_ = true;
  wall_start_ = std::chrono::steady_clock::now();
  sim_start_ = t0;
  SimulatorStatus ignored;
  CallMonitor(&ignored);
}

void Simulator::PaceRealTime() {
  if (realtime_rate_ <= 0.0) return;
  const double sim_elapsed = context_->get_time() - sim_start_;
  const auto target = wall_start_ + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                                        std::chrono::duration<double>(sim_elapsed / realtime_rate_));
  std::this_thread::sleep_until(target);
}

void Simulator::set_step_limit(int64_t steps) {
  if (steps < 1) {
    throw std::invalid_argument("Simulator::set_step_limit: the limit must be >= 1 step; got " +
                                cairn::FormatShort(steps) + ".");
  }
  step_limit_ = steps;
}

void Simulator::CheckStepBudget(double t_final) {
  const double t = context_->get_time();
  const double span = t_final - t;
  if (span <= 0.0) return;
  // A lower bound on the steps: every step is at most the maximum step size, and the simulator stops at every
  // event time.
  double steps = 0.0;
  std::string cause;
  if (system_.num_continuous_states() > 0) {
    steps = span / integrator_->maximum_step_size();
    cause = "integrator steps of at most " + FormatShort(integrator_->maximum_step_size()) + " s";
  }
  const std::vector<LeafAndContext> leaves = initialized_ ? leaves_ : system_.CollectLeafSystems(context_.get());
  for (const LeafAndContext& leaf : leaves) {
    for (const Event& event : leaf.system->declared_events()) {
      if (event.trigger != TriggerType::kPeriodic) continue;
      const double period = event.periodic.period;
      if (span / period > steps) {
        steps = span / period;
        cause = "a periodic event of '" + leaf.system->GetPathName() + "' every " + FormatShort(period) + " s";
      }
    }
  }
  if (steps > static_cast<double>(step_limit_)) {
    throw std::invalid_argument("AdvanceTo(" + FormatShort(t_final) + "): simulating " + FormatShort(span) +
                                " s from t = " + FormatShort(t) + " takes at least " + FormatShort(steps) +
                                " steps (" + cause + "), more than the limit of " + cairn::FormatShort(step_limit_) +
                                " (Simulator::set_step_limit); shorten the simulated time or lengthen the step or "
                                "period.");
  }
  for (const LeafAndContext& leaf : leaves) {
    for (const Event& event : leaf.system->declared_events()) {
      if (event.trigger != TriggerType::kPeriodic || !SameTime(t_final + event.periodic.period, t_final)) continue;
      throw std::invalid_argument("AdvanceTo(" + FormatShort(t_final) + "): the period " +
                                  FormatShort(event.periodic.period) + " s of a periodic event of '" +
                                  leaf.system->GetPathName() +
                                  "' is below the time resolution there (event times closer than 1e-12 relative "
                                  "coincide); use a longer period or a shorter simulation.");
    }
  }
}

SimulatorStatus Simulator::AdvanceTo(double t_final) {
  if (!std::isfinite(t_final) || t_final < context_->get_time()) {
    throw std::invalid_argument("AdvanceTo(" + FormatShort(t_final) + "): the time must be finite and not before "
                                "the current time " + FormatShort(context_->get_time()) + ".");
  }
  CheckStepBudget(t_final);
  if (!initialized_) Initialize();
  SimulatorStatus status;
  // A stop reported by the initialization events ends the first AdvanceTo() at once.
  if (StopsRun(initialization_status_, &status)) {
    initialization_status_ = EventStatus::DidNothing();
    return status;
  }
  std::vector<internal::TriggeredEvent> due;
  int64_t steps_here = 0;
  while (context_->get_time() < t_final) {
    if (steps_here == step_limit_) {
      throw std::runtime_error("AdvanceTo(" + FormatShort(t_final) + ") took " + cairn::FormatShort(step_limit_) +
                               " steps, the limit (Simulator::set_step_limit), and reached only t = " +
                               FormatShort(context_->get_time()) +
                               "; the integrator's steps are small (loosen its accuracy or check the dynamics), "
                               "or raise the limit.");
    }
    ++steps_here;
    // The context may have been changed since the last step; the set of leaves cannot, the events can't either.
    const EventStatus updated = ApplyUpdates(pending_updates_);
    pending_updates_.clear();
    if (StopsRun(updated, &status)) return status;

    const double t = context_->get_time();
    const double next_event = NextPeriodicEvents(t, /*inclusive=*/false, &due);
    const double t_target = std::min(next_event, t_final);
    const bool hits_event = next_event <= t_final;
    double reached = t_target;
    if (system_.num_continuous_states() > 0) {
      reached = integrator_->Step(system_, context_.get(), t_target);
    } else {
      context_->SetTime(t_target);
    }
    ++num_steps_;
    if (!(hits_event && reached == t_target)) due.clear();
    Split(due, EventKind::kUnrestrictedUpdate, &pending_updates_);
    Split(due, EventKind::kDiscreteUpdate, &pending_updates_);
    const EventStatus published = Publish(due);
    if (StopsRun(published, &status)) return status;
    PaceRealTime();
    if (CallMonitor(&status)) return status;
  }
  status.reason = SimulatorStatus::Reason::kReachedBoundaryTime;
  status.time = context_->get_time();
  return status;
}

}  // namespace cairn::systems
