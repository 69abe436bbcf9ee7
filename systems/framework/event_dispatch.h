#pragma once

#include <vector>

#include "cairn/systems/framework/event.h"
#include "cairn/systems/framework/system.h"

namespace cairn::systems::internal {

/// One event of one leaf system, due now, with the leaf's context.
struct TriggeredEvent {
  const LeafSystem* system;
  Context* context;
  const Event* event;
};

/// Appends the events of `leaves` with the given trigger (and kind), keeping leaf order and declaration order.
void CollectEvents(const std::vector<LeafAndContext>& leaves, TriggerType trigger, EventKind kind,
                   std::vector<TriggeredEvent>* events);

/// Runs unrestricted updates: every leaf's next state is computed from the current values of all contexts
/// first, then all are applied, so the order of leaves does not matter. Several events of one leaf apply in
/// declaration order to the same next state. Returns the most severe status, its message prefixed with the
/// system's path name; if any handler failed, no update is applied.
EventStatus ApplyUnrestrictedUpdates(const std::vector<TriggeredEvent>& events);

/// As ApplyUnrestrictedUpdates(), for discrete updates.
EventStatus ApplyDiscreteUpdates(const std::vector<TriggeredEvent>& events);

/// Runs publish events in order (all of them, whatever they report); returns the most severe status.
EventStatus DispatchPublishes(const std::vector<TriggeredEvent>& events);

/// Runs all events of one trigger in the order unrestricted updates, discrete updates, publishes, stopping after
/// the first group that fails; returns the most severe status.
EventStatus ExecuteAll(const std::vector<LeafAndContext>& leaves, TriggerType trigger);

}  // namespace cairn::systems::internal
