#include "cairn/systems/framework/event_dispatch.h"

#include <string>
#include <utility>

#include "cairn/systems/framework/leaf_system.h"

namespace cairn::systems::internal {

void CollectEvents(const std::vector<LeafAndContext>& leaves, TriggerType trigger, EventKind kind,
                   std::vector<TriggeredEvent>* events) {
  for (const LeafAndContext& leaf : leaves) {
    for (const Event& event : leaf.system->declared_events()) {
      if (event.trigger == trigger && event.kind == kind) events->push_back({leaf.system, leaf.context, &event});
    }
  }
}

namespace {

// A handler's status with the system's path name in front of its message.
EventStatus Attributed(const TriggeredEvent& triggered, EventStatus status) {
  if (!status.stops()) return status;
  const std::string message = triggered.system->GetPathName() + ": " + status.message();
  return status.failed() ? EventStatus::Failed(message) : EventStatus::ReachedTermination(message);
}

// Events arrive grouped by leaf (CollectEvents keeps leaf order), so one pass finds each leaf's run of events.
template <typename Next, typename MakeNext, typename Apply, typename Commit>
EventStatus ComputeThenCommit(const std::vector<TriggeredEvent>& events, MakeNext make_next, Apply apply,
                              Commit commit) {
  EventStatus status = EventStatus::DidNothing();
  std::vector<std::pair<Context*, Next>> pending;
  for (const TriggeredEvent& triggered : events) {
    if (pending.empty() || pending.back().first != triggered.context) {
      pending.emplace_back(triggered.context, make_next(*triggered.context));
    }
    status.KeepMoreSevere(Attributed(triggered, apply(triggered, &pending.back().second)));
  }
  if (status.failed()) return status;
  for (auto& [context, next] : pending) commit(context, next);
  return status;
}

}  // namespace

EventStatus ApplyUnrestrictedUpdates(const std::vector<TriggeredEvent>& events) {
  return ComputeThenCommit<State>(
      events, [](const Context& context) { return context.CloneState(); },
      [](const TriggeredEvent& e, State* next) { return e.event->unrestricted_update(*e.context, next); },
      [](Context* context, const State& next) { context->SetState(next); });
}

EventStatus ApplyDiscreteUpdates(const std::vector<TriggeredEvent>& events) {
  return ComputeThenCommit<DiscreteValues>(
      events, [](const Context& context) { return context.get_discrete_state(); },
      [](const TriggeredEvent& e, DiscreteValues* next) { return e.event->discrete_update(*e.context, next); },
      [](Context* context, const DiscreteValues& next) { context->SetDiscreteState(next); });
}

EventStatus DispatchPublishes(const std::vector<TriggeredEvent>& events) {
  EventStatus status = EventStatus::DidNothing();
  for (const TriggeredEvent& e : events) status.KeepMoreSevere(Attributed(e, e.event->publish(*e.context)));
  return status;
}

EventStatus ExecuteAll(const std::vector<LeafAndContext>& leaves, TriggerType trigger) {
  std::vector<TriggeredEvent> events;
  CollectEvents(leaves, trigger, EventKind::kUnrestrictedUpdate, &events);
  EventStatus status = ApplyUnrestrictedUpdates(events);
  if (status.failed()) return status;
  events.clear();
  CollectEvents(leaves, trigger, EventKind::kDiscreteUpdate, &events);
  status.KeepMoreSevere(ApplyDiscreteUpdates(events));
  if (status.failed()) return status;
  events.clear();
  CollectEvents(leaves, trigger, EventKind::kPublish, &events);
  status.KeepMoreSevere(DispatchPublishes(events));
  return status;
}

}  // namespace cairn::systems::internal
