#pragma once

#include <memory>
#include <string>
#include <vector>

#include <Eigen/Core>

#include <cairn/multibody/data.h>
#include <cairn/multibody/model.h>
#include <cairn/systems/framework/leaf_system.h>

namespace cairn::planning {

/// Feedforward torques that hold every part of the robot that stands on nothing against gravity, so the PD drive
/// tracks the reference instead of sagging below it. For a joint whose subtree holds no loaded sole (the arms, the
/// neck, the waist under the upper body, a swinging leg) the static torque is exact whatever the contacts do: it is
/// the joint's entry of the generalized gravity force g(q) (multibody::GravityTorques at the measured q). A joint on
/// the chain from the base to a loaded sole shares its load with the ground through forces this system does not
/// know, so it gets none (its PD drive carries it, as without this system). Without it a swinging leg hangs some
/// millimetres low and lands early, still moving (docs/walk.md, "Touchdown and RCOF").
///
/// | port | type | meaning |
/// |---|---|---|
/// | input `state` | vector nq + nv | the plant's measured [q; v] (HumanoidPlant's `state`) |
/// | input `contacts` | std::vector<multibody::SoleState> | the plant's left and right sole (HumanoidPlant's `contacts`) |
/// | output `torque` | vector nv | gain times g(q) on the joints that carry no loaded sole, 0 elsewhere and on the base (HumanoidPlant's `torque`) |
class GravityFeedforward final : public systems::LeafSystem {
 public:
  /// `sole_bodies` names the left and the right sole body or frame, in the order of the `contacts` input. `gain`
  /// scales the torques, in [0, 1]. Throws std::invalid_argument for a null model, one without a floating base, a
  /// sole that is not a body or frame of the model, or a gain outside [0, 1].
  GravityFeedforward(std::shared_ptr<const multibody::Model> model, std::vector<std::string> sole_bodies,
                     double gain = 1.0);

  const systems::InputPort& get_state_input_port() const { return GetInputPort("state"); }
  const systems::InputPort& get_contacts_input_port() const { return GetInputPort("contacts"); }
  const systems::OutputPort& get_torque_output_port() const { return GetOutputPort("torque"); }

  /// The torques the output computes for configuration q (size nq) with `left_loaded` / `right_loaded` saying which
  /// soles stand. Throws std::invalid_argument for a q of the wrong size.
  Eigen::VectorXd Torques(const Eigen::VectorXd& q, bool left_loaded, bool right_loaded) const;

  double gain() const { return gain_; }

 private:
  void Compute(const Eigen::Ref<const Eigen::VectorXd>& q, bool left_loaded, bool right_loaded, multibody::Data* data,
               Eigen::VectorXd* torque) const;

  std::shared_ptr<const multibody::Model> model_;
  double gain_;
  // Per sole: 0 on the velocity coordinates of its chain to the world, 1 elsewhere.
  Eigen::VectorXd off_chain_[2];
  int scratch_{-1};
};

}  // namespace cairn::planning
