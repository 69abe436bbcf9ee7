#pragma once

/// @file
/// InteractionPlanner: haptic interaction planning and confidence-based pruning (§3.5–3.6) as a system.

#include <Eigen/Core>

#include "cairn/perception/haptics/haptic_interaction_planner.h"
#include "cairn/perception/haptics/traversability_memory.h"
#include "cairn/systems/framework/leaf_system.h"

namespace cairn::perception {

/// Plans where the antenna should touch the object in view, pruned by the memory's confidence (eqs. 16–21).
///
/// | port | type | meaning |
/// |---|---|---|
/// | input `object_C` | Eigen::Matrix3Xd | the object's points (ObjectDescriptor's `object_C`) |
/// | input `recall` | AffordanceRecall | the memory's answer for the object (AffordanceMemory's `recall`) |
/// | output `plan` | InteractionPlan | candidates, the selected points in execution order, antenna targets in C |
///
/// Stateless; the output depends on both inputs. A plan over a few hundred voxels costs well under a
/// millisecond, and it is deterministic, so it is computed in the output rather than in an event.
class InteractionPlanner final : public systems::LeafSystem {
 public:
  /// Throws std::invalid_argument for invalid options.
  explicit InteractionPlanner(const HapticInteractionPlanner::Options& options);
  /// The paper's options.
  InteractionPlanner();

  const HapticInteractionPlanner& planner() const { return planner_; }

  const systems::InputPort& get_object_input_port() const { return get_input_port(0); }
  const systems::InputPort& get_recall_input_port() const { return get_input_port(1); }
  const systems::OutputPort& get_plan_output_port() const { return get_output_port(0); }

 private:
  HapticInteractionPlanner planner_;
};

}  // namespace cairn::perception
