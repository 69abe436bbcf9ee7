#pragma once

#include <memory>

#include <cairn/multibody/model.h>
#include <cairn/planning/stabilization/stabilized_trajectory.h>
#include <cairn/planning/stabilization/stabilizer_options.h>
#include <cairn/planning/trajectory/whole_body_trajectory.h>
#include <cairn/systems/framework/leaf_system.h>

namespace cairn::planning {

/// Interpolation and ZMP stabilisation as a block (thesis 2.5.1c, Fig. 5.1): StabilizeTrajectory() on the
/// whole-body trajectory at its input.
///
/// | port | type | meaning |
/// |---|---|---|
/// | input `trajectory` | WholeBodyTrajectory | waypoints (TrajectoryOptimizer's `trajectory`) |
/// | output `reference` | StabilizedTrajectory | dense q, v at the control rate, reference and model ZMP, report |
///
/// The stabilisation is expensive (inverse kinematics at every sample, several passes), so it runs in events and
/// its result lives in abstract state that the output only copies: at initialization, on ExecuteForcedEvents,
/// and at every simulator step whose input differs from the trajectory the state was computed from (abstract
/// state 0 keeps that source), so a Stabilizer behind a TrajectoryOptimizer that solves at initialization picks up
/// the solved trajectory at the first step. A trajectory that is not found, or that StabilizeTrajectory rejects,
/// gives an empty reference whose report says why (report.success false); it is not an error of the simulation.
class Stabilizer final : public systems::LeafSystem {
 public:
  /// Throws std::invalid_argument for a null model or options out of range (ValidateStabilizerOptions).
  Stabilizer(std::shared_ptr<const multibody::Model> model, const StabilizerOptions& options);

  const systems::InputPort& get_trajectory_input_port() const { return GetInputPort("trajectory"); }
  const systems::OutputPort& get_reference_output_port() const { return GetOutputPort("reference"); }

  /// The options.
  const StabilizerOptions& options() const { return options_; }

 private:
  systems::EventStatus Update(const systems::Context& context, systems::State* next, bool only_if_changed) const;

  std::shared_ptr<const multibody::Model> model_;
  StabilizerOptions options_;
  int source_state_{};
  int reference_state_{};
};

}  // namespace cairn::planning
