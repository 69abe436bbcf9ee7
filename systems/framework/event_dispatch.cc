#include "cairn/systems/framework/event_dispatch.h"

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

// Events arrive grouped by leaf (CollectEvents keeps leaf order), so one pass finds each leaf's run of events.
template <typename Next, typename MakeNext, typename Apply, typename Commit>
void ComputeThenCommit(const std::vector<TriggeredEvent>& events, MakeNext make_next, Apply apply, Commit commit) {
  std::vector<std::pair<Context*, Next>> pending;
  for (const TriggeredEvent& triggered : events) {
    if (pending.empty() || pending.back().first != triggered.context) {
      pending.emplace_back(triggered.context, make_next(*triggered.context));
    }
    apply(triggered, &pending.back().second);
  }
  for (auto& [context, next] : pending) commit(context, next);
}

}  // namespace

void ApplyUnrestrictedUpdates(const std::vector<TriggeredEvent>& events) {
  ComputeThenCommit<State>(
      events, [](const Context& context) { return context.CloneState(); },
      [](const TriggeredEvent& e, State* next) { e.event->unrestricted_update(*e.context, next); },
      [](Context* context, const State& next) { context->SetState(next); });
}

void ApplyDiscreteUpdates(const std::vector<TriggeredEvent>& events) {
  ComputeThenCommit<DiscreteValues>(
      events, [](const Context& context) { return context.get_discrete_state(); },
      [](const TriggeredEvent& e, DiscreteValues* next) { e.event->discrete_update(*e.context, next); },
      [](Context* context, const DiscreteValues& next) { context->SetDiscreteState(next); });
}

void DispatchPublishes(const std::vector<TriggeredEvent>& events) {
  for (const TriggeredEvent& e : events) e.event->publish(*e.context);
}

void ExecuteAll(const std::vector<LeafAndContext>& leaves, TriggerType trigger) {
  std::vector<TriggeredEvent> events;
  CollectEvents(leaves, trigger, EventKind::kUnrestrictedUpdate, &events);
  ApplyUnrestrictedUpdates(events);
  events.clear();
  CollectEvents(leaves, trigger, EventKind::kDiscreteUpdate, &events);
  ApplyDiscreteUpdates(events);
  events.clear();
  CollectEvents(leaves, trigger, EventKind::kPublish, &events);
  DispatchPublishes(events);
}

}  // namespace cairn::systems::internal
