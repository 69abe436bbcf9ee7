#pragma once

#include <memory>

#include <Eigen/Core>

#include <cairn/multibody/model.h>
#include <cairn/planning/stabilization/stabilized_trajectory.h>
#include <cairn/systems/framework/leaf_system.h>

namespace cairn::planning {

/// Plays a stabilised reference into a plant: the Stabilizer's dense samples as the [q; v] vector a
/// HumanoidPlant's `reference` input expects, at the context's time.
///
/// | port | type | meaning |
/// |---|---|---|
/// | input `reference` | StabilizedTrajectory | dense q, v at the control rate (Stabilizer's `reference`) |
/// | output `reference` | vector nq + nv | [q; v] at the context's time |
///
/// Between two control samples the joints and the base position are interpolated linearly and the base
/// quaternion on the sphere (slerp), so a plant stepping faster than the control rate sees no staircase; v is
/// interpolated linearly. Before the first sample the first is held; after the last one its configuration is held
/// with zero velocity (the reference has stopped, so the PD drive should not chase the last sample's motion). The
/// calculation is a cheap lookup, so it is an output calculation, not an event. An empty reference (a Stabilizer
/// that has not run yet, or whose trajectory was not found) has no motion to play: evaluating the output then
/// throws std::runtime_error quoting the reference's report, instead of sending the plant an invented posture.
class StabilizedReferencePlayer final : public systems::LeafSystem {
 public:
  /// Throws std::invalid_argument for a null model or one without a floating base (the quaternion at q[3..6]).
  explicit StabilizedReferencePlayer(std::shared_ptr<const multibody::Model> model);

  const systems::InputPort& get_reference_input_port() const { return GetInputPort("reference"); }
  const systems::OutputPort& get_reference_output_port() const { return GetOutputPort("reference"); }

  /// [q; v] of `reference` at time `t` as the output computes it. Throws std::runtime_error for an empty
  /// reference, std::invalid_argument for samples of the wrong size or a t that is not finite.
  Eigen::VectorXd Sample(const StabilizedTrajectory& reference, double t) const;

 private:
  std::shared_ptr<const multibody::Model> model_;
};

}  // namespace cairn::planning
