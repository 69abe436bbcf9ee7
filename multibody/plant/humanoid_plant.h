#pragma once

#include <memory>
#include <vector>

#include <Eigen/Core>

#include <cairn/multibody/model.h>
#include <cairn/multibody/plant/humanoid_measurements.h>
#include <cairn/multibody/plant/humanoid_plant_options.h>
#include <cairn/multibody/plant/joint_pd_controller.h>
#include <cairn/multibody/plant/terrain_box.h>
#include <cairn/systems/framework/leaf_system.h>

namespace cairn::multibody {

/// A humanoid walking in Bullet under joint PD position control, as a block: every time step it computes the
/// PD torques toward the reference (plus the optional feedforward torque), saturates them at the effort limits,
/// steps the BulletPlant and updates the ContactMonitor. A detected fall ends the simulation with its reason
/// (EventStatus::ReachedTermination) unless options.stop_on_fall is false.
///
/// | port | type | meaning |
/// |---|---|---|
/// | input `reference` | vector nq + nv | desired [q; v] (floating-base entries ignored) |
/// | input `torque` | vector nv (only with options.torque_input) | feedforward joint torques (N m), added before saturation |
/// | output `state` | vector nq + nv | [q; v] in Cairn's coordinates (the discrete state; no feedthrough) |
/// | output `contacts` | abstract std::vector<SoleState> | left and right sole: wrench, CoP, loaded |
/// | output `slips` | abstract std::vector<SlipEvent> | every slip so far |
/// | output `stances` | abstract std::vector<StancePhase> | every stance so far, with its RCOF (eq. 2.2) |
/// | output `zmp` | vector 3 | ZMP from the foot contacts (NaN in the air) |
/// | output `energy` | vector 3 | [E_COM (eq. 2.1), E_ele (eq. 2.6), E_ele's Joule heat Σ R I² dt] in J, accumulated |
///
/// State: discrete group 0 is [q; v]; abstract state 0 the HumanoidMeasurements. The Bullet world lives in
/// per-context storage and follows the context's state: when the state was changed from outside (SetDiscreteState)
/// the world is reset to it before the next step (losing only the contact solver's warm start). Periodic
/// unrestricted update every options.bullet.time_step starting at t = 0, so at time t the state is the plant's at t.
class HumanoidPlant final : public systems::LeafSystem {
 public:
  /// Builds the plant from a floating-base `model`, its terrain, PD gains and options; the initial state is
  /// `initial_q` with zero velocity. Throws std::invalid_argument as BulletPlant, ContactMonitor do, and for an
  /// initial_q of the wrong size or a model without a floating base.
  HumanoidPlant(const Model& model, std::vector<TerrainBox> terrain, const JointPdController& controller,
                const Eigen::VectorXd& initial_q, HumanoidPlantOptions options = HumanoidPlantOptions());
  ~HumanoidPlant() override;

  /// The model.
  const Model& model() const { return model_; }
  /// The options.
  const HumanoidPlantOptions& options() const { return options_; }
  /// Everything the plant has measured so far in `context` (its abstract state): what the outputs show, plus
  /// whether and why it fell, which the outputs do not (a run with stop_on_fall false goes on after a fall).
  const HumanoidMeasurements& measurements(const systems::Context& context) const { return Measurements(context); }

 private:
  struct Engine;
  class EngineHandle;

  systems::EventStatus Update(const systems::Context& context, systems::State* next) const;
  const HumanoidMeasurements& Measurements(const systems::Context& context) const;

  Model model_;
  std::vector<TerrainBox> terrain_;
  JointPdController controller_;
  HumanoidPlantOptions options_;
  int engine_storage_ = -1;
  int torque_port_ = -1;
};

}  // namespace cairn::multibody
