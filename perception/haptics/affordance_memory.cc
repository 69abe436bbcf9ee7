#include "cairn/perception/haptics/affordance_memory.h"

#include <cmath>
#include <stdexcept>

#include "cairn/common/number_text.h"
#include "cairn/systems/framework/state.h"

namespace cairn::perception {

AffordanceMemory::AffordanceMemory(const TraversabilityMemory& initial, double period, double offset)
    : period_(period) {
  if (!(period > 0.0) || !std::isfinite(period)) {
    throw std::invalid_argument("AffordanceMemory: period " + FormatShort(period) +
                                " s must be positive and finite (the sensor's frame period, e.g. 0.5)");
  }
  if (!(offset >= 0.0) || !std::isfinite(offset)) {
    throw std::invalid_argument("AffordanceMemory: offset " + FormatShort(offset) + " s must be non-negative");
  }
  DeclareAbstractInputPort("descriptor", systems::Value<AffordanceDescriptor>(AffordanceDescriptor(initial.lines())));
  HapticOutcome none;
  none.descriptor = AffordanceDescriptor(initial.lines());
  DeclareAbstractInputPort("outcome", systems::Value<HapticOutcome>(none));
  memory_state_ = DeclareAbstractState(systems::Value<TraversabilityMemory>(initial));
  sequence_state_ = DeclareAbstractState(systems::Value<int>(-1));
  const int memory = memory_state_;
  DeclareAbstractOutputPort(
      "recall", systems::Value<AffordanceRecall>(AffordanceRecall{}),
      [this, memory](const systems::Context& c, systems::AbstractValue* v) {
        v->get_mutable_value<AffordanceRecall>() = c.get_abstract_state<TraversabilityMemory>(memory).Recall(
            get_descriptor_input_port().Eval<AffordanceDescriptor>(c));
      },
      {abstract_state_ticket(memory), input_port_ticket(0)});
  DeclareAbstractOutputPort(
      "memory", systems::Value<TraversabilityMemory>(initial),
      [memory](const systems::Context& c, systems::AbstractValue* v) { v->SetFrom(c.get_abstract_state_value(memory)); },
      {abstract_state_ticket(memory)});
  DeclarePeriodicUnrestrictedUpdateEvent(period, offset, &AffordanceMemory::Learn);
}

void AffordanceMemory::Learn(const systems::Context& context, systems::State* next) const {
  const HapticOutcome& outcome = get_outcome_input_port().Eval<HapticOutcome>(context);
  int& last = next->get_mutable_abstract_state<int>(sequence_state_);
  if (outcome.sequence <= last) return;
  next->get_mutable_abstract_state<TraversabilityMemory>(memory_state_).Add(outcome.descriptor, outcome.traversable);
  last = outcome.sequence;
}

}  // namespace cairn::perception
