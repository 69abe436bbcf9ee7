#pragma once

/// @file
/// ProbeController: the probing arm's force into collapsibility (seed 001 §5.1), as a system.

#include "cairn/perception/terrain/collapsibility_estimator.h"
#include "cairn/systems/framework/leaf_system.h"

namespace cairn::perception {

/// While the `probing` input is on (>= 0.5), samples the force sensor every `period` seconds into a
/// CollapsibilityEstimator (sliding-window average, eq. 5); a new probe (the input switching on) starts from an
/// empty window. The output holds C of the current or last probe.
///
/// | port | type | meaning |
/// |---|---|---|
/// | input `force` | vector of size 1 | normal force at the probe's tip, N |
/// | input `probing` | vector of size 1 | 1 while the arm pushes into the ground, else 0 |
/// | output `collapsibility` | vector of size 2 | [C (NaN before the first sample), samples in the window] |
///
/// State: the estimator (abstract) and whether the last sample was taken while probing (discrete), updated by a
/// periodic unrestricted update; the output depends on the state only.
class ProbeController final : public systems::LeafSystem {
 public:
  /// Throws std::invalid_argument for a non-positive or non-finite period or bad estimator options.
  ProbeController(const CollapsibilityEstimator::Options& options, double period);

  const systems::InputPort& get_force_input_port() const { return get_input_port(0); }
  const systems::InputPort& get_probing_input_port() const { return get_input_port(1); }
  const systems::OutputPort& get_collapsibility_output_port() const { return get_output_port(0); }

 private:
  void Update(const systems::Context& context, systems::State* next) const;

  int estimator_state_{};
  int flag_state_{};
};

}  // namespace cairn::perception
