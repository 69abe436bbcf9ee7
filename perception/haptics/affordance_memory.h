#pragma once

/// @file
/// AffordanceMemory: the growing traversability memory (§3.4) as a block-diagram system.

#include "cairn/perception/haptics/haptic_outcome.h"
#include "cairn/perception/haptics/traversability_memory.h"
#include "cairn/systems/framework/leaf_system.h"

namespace cairn::perception {

/// Holds a TraversabilityMemory as abstract state and answers recalls for the descriptor on its input. Every
/// `period` seconds (from `offset`) a periodic unrestricted update adds the outcome on its `outcome` input when
/// its sequence number is newer than the last one added, so each interaction is learnt once.
///
/// | port | type | meaning |
/// |---|---|---|
/// | input `descriptor` | AffordanceDescriptor | the object in view |
/// | input `outcome` | HapticOutcome | the antenna's latest interaction (sequence -1: none) |
/// | output `recall` | AffordanceRecall | eqs. 11–15 for the input descriptor against the memory (state) |
/// | output `memory` | TraversabilityMemory | the memory itself (state only) |
///
/// State: the memory (abstract, initially `initial`) and the last sequence added (abstract int, -1).
class AffordanceMemory final : public systems::LeafSystem {
 public:
  /// Throws std::invalid_argument for a non-positive or non-finite period or a negative offset.
  AffordanceMemory(const TraversabilityMemory& initial, double period, double offset = 0.0);

  double period() const { return period_; }

  const systems::InputPort& get_descriptor_input_port() const { return get_input_port(0); }
  const systems::InputPort& get_outcome_input_port() const { return get_input_port(1); }
  const systems::OutputPort& get_recall_output_port() const { return get_output_port(0); }
  const systems::OutputPort& get_memory_output_port() const { return get_output_port(1); }

 private:
  void Learn(const systems::Context& context, systems::State* next) const;

  double period_;
  int memory_state_{};
  int sequence_state_{};
};

}  // namespace cairn::perception
