#pragma once

#include <memory>
#include <string>

#include <Eigen/Core>

#include <cairn/multibody/data.h>
#include <cairn/multibody/model.h>
#include <cairn/systems/framework/leaf_system.h>

namespace cairn::planning {

/// Settings of BalanceFeedback.
struct BalanceFeedbackOptions {
  /// Forward and sideways gains, rad of leg tilt per m of capture-point error, in [0, 1000] (0 turns the axis off).
  /// In the plant, pitch gains in [0.6, 1] with roll gains in [0.5, 2] walk a slow four-step plan that falls open loop
  /// and with a pitch gain of 0.3 or less (docs/walk.md, "Balance feedback"; measured before the foothold term);
  /// the defaults sit in the middle.
  double pitch_gain{0.8};
  double roll_gain{1.0};
  /// Largest ankle offsets, rad, in [0, 0.5].
  double max_pitch{0.2};
  double max_roll{0.15};
  /// COM height of the linear inverted pendulum whose capture point is fed back, m, in (0.1, 3]: omega = sqrt(g / h).
  double com_height{0.8};
  /// How much of each loaded foot's horizontal placement error (the measured sole's x-y against the reference's)
  /// is written into that leg's reference, in [0, 1]. The reference's leg angles place the sole where the plan put
  /// it relative to the planned base; a foot that landed elsewhere then fights the other foot in double support
  /// (both cannot be where their references say) and the base follows the misplaced foot. At 1 the loaded legs'
  /// references place the soles where they are, so the legs agree and the base tracks the plan. On the flat 3 m
  /// plan gains 0.3-1 walk to the end (fewest slips at 0.3-0.5) and 0.2 or less fall (docs/walk.md); 0 turns it
  /// off.
  double foothold_gain{0.5};
  /// How much of the swing sole's pose error that the base's own error causes is taken out of the swing leg's
  /// reference while the other foot stands, in [0, 1]: the rotation and the translation of the sole in the world
  /// that the measured base would give the reference's leg angles, against the reference's sole. The reference
  /// poses the swing sole relative to the planned base, so a base that leans 3 degrees (the tilt feedback leans it)
  /// lands the sole on its edge, early, and it slaps down and shears (docs/walk.md, "Touchdown and RCOF"). 0 turns
  /// it off.
  double swing_orientation_gain{0.0};
  double swing_position_gain{0.0};
  /// The sole frames of the left and the right leg (each on a chain of six joints below the floating base); needed
  /// only with a foothold or swing gain above 0.
  std::string left_sole{"l_sole"};
  std::string right_sole{"r_sole"};
  /// The ankle joints of the left and the right leg (revolute; pitch about the joints' +-y, roll about +-x).
  std::string left_ankle_pitch{"l_ankle_pitch"};
  std::string left_ankle_roll{"l_ankle_roll"};
  std::string right_ankle_pitch{"r_ankle_pitch"};
  std::string right_ankle_roll{"r_ankle_roll"};
};

/// Closes the walk's loop on the measured capture point. The stabilised reference is open loop: under PD tracking
/// the plant drifts from it, and the drift grows like exp(omega t) through every single support (omega ~ 3.5 /s for
/// an 0.8 m COM), so slow steps (0.9 s swings) fall where fast ones (0.6 s) do not. Every step this system compares
/// the plant's capture point xi = c + c_dot / omega with the reference's and tilts each loaded leg about its ankle
/// (an offset of the ankle pitch and roll references) so that the COM moves against the error, in the base's
/// heading frame:
///
///     leg tilt about y = -pitch_gain * e_forward,   leg tilt about x = +roll_gain * e_left   (clamped)
///
/// With the stiff PD drive and the sole flat on the ground the offset mostly re-poses the leg (the COM moves
/// h * tilt), with the ankle torque shifting the ZMP the same way. Swing legs are left alone (a tilted swing foot
/// would stub its toe).
///
/// Each loaded leg also takes foothold_gain times its sole's horizontal placement error (the plant's sole against
/// the reference's) into its six joint references, by one damped step of the leg's inverse kinematics with the base
/// held, so that two feet that did not land where planned do not fight each other in double support. While one leg
/// stands, the other (swinging) leg's reference takes out swing_orientation_gain of its sole's rotation error and
/// swing_position_gain of its translation error that the measured base's deviation from the planned base causes,
/// by the same inverse-kinematics step, so that the sole lands level and where planned in the world. The feedback
/// is a cheap calculation on the current inputs (no allocation), so it is an output.
///
/// | port | type | meaning |
/// |---|---|---|
/// | input `reference` | vector nq + nv | the planned [q; v] (StabilizedReferencePlayer's `reference`) |
/// | input `state` | vector nq + nv | the plant's measured [q; v] (HumanoidPlant's `state`) |
/// | input `contacts` | std::vector<multibody::SoleState> | the plant's left and right sole (HumanoidPlant's `contacts`): which carry load |
/// | output `reference` | vector nq + nv | `reference` with the loaded legs' ankle offsets and foothold corrections and the swing leg's correction |
class BalanceFeedback final : public systems::LeafSystem {
 public:
  /// Throws std::invalid_argument for a null model, one without a floating base or without gravity along -z, an
  /// ankle joint that is missing or not revolute about its x (roll) or y (pitch) axis, options out of range
  /// (naming the option and its range), and with a foothold or swing gain above 0 a sole frame that is missing or
  /// not on a six-joint leg below the floating base.
  BalanceFeedback(std::shared_ptr<const multibody::Model> model, const BalanceFeedbackOptions& options = {});

  const systems::InputPort& get_reference_input_port() const { return GetInputPort("reference"); }
  const systems::InputPort& get_state_input_port() const { return GetInputPort("state"); }
  const systems::InputPort& get_contacts_input_port() const { return GetInputPort("contacts"); }
  const systems::OutputPort& get_reference_output_port() const { return GetOutputPort("reference"); }

  const BalanceFeedbackOptions& options() const { return options_; }

  /// The corrected reference as the output computes it, with `left_loaded` / `right_loaded` saying which legs
  /// stand (for tests and offline use). Throws std::invalid_argument for vectors of the wrong size.
  Eigen::VectorXd Correct(const Eigen::VectorXd& reference, const Eigen::VectorXd& state, bool left_loaded,
                          bool right_loaded) const;

 private:
  struct Ankle {
    int q{0};         // index in q
    double sign{1.0};  // the sign of the joint axis along its tilt axis
  };

  // Adds the offsets to *y (a copy of `reference`); `measured` and `planned` are kinematics scratch.
  void Apply(const Eigen::VectorXd& reference, const Eigen::VectorXd& state, bool left_loaded, bool right_loaded,
             multibody::Data* measured, multibody::Data* planned, Eigen::MatrixXd* jacobian, Eigen::VectorXd* y) const;

  std::shared_ptr<const multibody::Model> model_;
  BalanceFeedbackOptions options_;
  Ankle pitch_[2], roll_[2];
  // Whether a term re-poses the legs (and so needs the sole frames and the legs' joints).
  bool uses_legs() const {
    return options_.foothold_gain > 0.0 || options_.swing_orientation_gain > 0.0 || options_.swing_position_gain > 0.0;
  }

  int sole_frame_[2]{-1, -1};
  int leg_v_[2][6]{};  // each leg's velocity indices, from the sole up
  int leg_q_[2][6]{};
  int scratch_{-1};
};

}  // namespace cairn::planning
