#pragma once

#include <functional>
#include <string>

#include "cairn/systems/framework/event_status.h"

namespace cairn::systems {

class Context;
class DiscreteValues;
class State;

/// What makes an event happen.
enum class TriggerType {
  kInitialization,  ///< Once, in Simulator::Initialize().
  kPeriodic,        ///< At offset + k * period, k = 0, 1, ...; the simulator lands exactly on these times.
  kPerStep,         ///< Every simulator step.
  kForced,          ///< Only when asked: System::ForcedPublish() / System::ExecuteForcedEvents().
};

/// What an event does.
enum class EventKind {
  kPublish,             ///< Reads the context, changes nothing in it (logging, printing, visualising).
  kDiscreteUpdate,      ///< Computes the next discrete state.
  kUnrestrictedUpdate,  ///< Computes the next state, any part of it (e.g. abstract state).
};

/// A periodic event's timing.
struct PeriodicEventData {
  double period{0.0};
  double offset{0.0};
};

/// An event declared by a leaf system: its trigger, its kind and the one handler matching that kind. Handlers
/// return an EventStatus (LeafSystem wraps handlers that return void as succeeded).
struct Event {
  TriggerType trigger{TriggerType::kForced};
  EventKind kind{EventKind::kPublish};
  PeriodicEventData periodic;
  std::function<EventStatus(const Context&)> publish;
  std::function<EventStatus(const Context&, DiscreteValues*)> discrete_update;
  std::function<EventStatus(const Context&, State*)> unrestricted_update;
};

}  // namespace cairn::systems
