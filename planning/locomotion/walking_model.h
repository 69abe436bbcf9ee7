#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <string>

#include <Eigen/Core>

#include <cairn/multibody/model.h>
#include <cairn/planning/locomotion/leg_torque_table.h>
#include <cairn/planning/locomotion/step_cost_model.h>

namespace cairn::planning {

/// Electrical constants of one joint drive, for the heat term of the thesis' electrical energy (eq. 2.6):
/// a joint torque tau draws the motor current I = tau / (gear_ratio * torque_constant) and dissipates R I^2.
struct MotorConstants {
  double resistance{0.0};       ///< armature (terminal) resistance R, ohm
  double torque_constant{0.0};  ///< K_tau, N m / A
  double gear_ratio{0.0};       ///< r, joint speed to motor speed
};

/// The leg geometry a walking pattern needs, extracted from the multibody model at the zero (standing)
/// configuration. Lengths in metres; all positions in the pelvis frame (x forward, y left, z up) of the LEFT leg
/// (the right leg is its mirror image, y -> -y).
struct LegGeometry {
  Eigen::Vector3d hip_from_com{Eigen::Vector3d::Zero()};  ///< left hip centre (hip axes' intersection) - COM
  double thigh_length{0.0};   ///< hip centre to knee axis
  double shank_length{0.0};   ///< knee axis to ankle centre (ankle axes' intersection)
  double ankle_height{0.0};   ///< ankle centre above the sole
  double ankle_forward{0.0};  ///< ankle centre ahead of the sole centre (negative: behind), sole frame
  double knee_flexion_min{0.0};  ///< walking range of the knee (rad), from the YAML
  double knee_flexion_max{0.0};
  double leg_length_min{0.0};  ///< hip-to-ankle distance at knee_flexion_max
  double leg_length_max{0.0};  ///< hip-to-ankle distance at knee_flexion_min
  double com_height_standing{0.0};  ///< COM above the soles at the zero configuration
};

/// A robot as the footstep planner sees it: reach, step-parameter bounds, foot and body boxes, leg geometry,
/// drive constants and the static leg-torque table, loaded from a walking YAML next to the robot's URDF
/// (`data/robots/cairn_humanoid_walking.yaml`, documented in data/robots/README.md).
///
/// Immutable and cheap to copy (the multibody model and tables are shared); thread-safe to share.
///
/// Leg joints are numbered hip yaw, hip roll, hip pitch, knee, ankle pitch, ankle roll (0..5), the URDF's order.
class WalkingModel {
 public:
  /// Number of actuated joints per leg.
  static constexpr int kLegJoints = 6;

  /// Reads the walking YAML at `yaml_path` and the URDF it names (relative to the YAML's folder). Throws
  /// std::invalid_argument naming the file, the line and the key for an unreadable or malformed file, a missing,
  /// unknown, repeated or mistyped key, a number out of its valid range (every number is validated) or a
  /// parameter range the leg geometry cannot realise (the message gives the range the legs allow), and
  /// std::runtime_error for a URDF that cannot be read or whose legs do not fit the keys.
  static WalkingModel Load(const std::string& yaml_path);

  /// Robot name (the YAML's `name`: 1 to 64 letters, digits, '_', '-' or '.', since it names cache files).
  const std::string& name() const;
  /// Total mass from the multibody model, kg.
  double mass() const;
  /// Gravity magnitude, m/s^2 (from the multibody model).
  double gravity() const;
  /// Reachable step displacements (thesis 2.3.3).
  const StepReach& reach() const;
  /// Lower bounds of the step parameters.
  const StepParameters& parameter_lower() const;
  /// Upper bounds of the step parameters.
  const StepParameters& parameter_upper() const;
  /// Sole length (x) and width (y), m, from the multibody model's sole collision box.
  double foot_length() const;
  double foot_width() const;
  /// Half extents of a box around the body above the knees, from the multibody model's collision geometry at
  /// the standing (zero) configuration: x and y are the largest distances of any such geometry from the pelvis
  /// axis (so the box is centred on it), z spans from body_box_bottom() up to the top of the head lowered by the
  /// YAML's `body_box.crouch` (thesis 2.5.2: 20 cm). For the planner's collision check: place it over the
  /// midpoint of a stance, turned with the stance.
  const Eigen::Vector3d& body_half_extents() const;
  /// Height of that box's lower face above the soles (the knees' height at the standing posture), m.
  double body_box_bottom() const;
  /// Leg geometry extracted from the URDF.
  const LegGeometry& leg() const;
  /// Drive constants of leg joint `i` (0..5; both legs use the same drives).
  const MotorConstants& motor(int i) const;
  /// Names of the left leg's joints in the URDF, in leg-joint order.
  const std::array<std::string, kLegJoints>& left_leg_joint_names() const;
  /// Apex height of the swing ankle above the straight line between lift-off and touch-down, m.
  double swing_height() const;
  /// Static torques of one stance leg over leg postures, precomputed at load (see LegTorqueTable).
  const LegTorqueTable& leg_torques() const;
  /// The multibody model.
  const multibody::Model& multibody() const;
  /// 64-bit FNV-1a hash of the YAML and URDF file contents, written into oracle files to detect model changes.
  std::uint64_t content_hash() const;
  /// The YAML file this model was loaded from.
  const std::string& yaml_path() const;
  /// The URDF file the YAML names (resolved path).
  const std::string& urdf_path() const;

 private:
  struct Impl;
  explicit WalkingModel(std::shared_ptr<const Impl> impl);
  std::shared_ptr<const Impl> impl_;
};

}  // namespace cairn::planning
