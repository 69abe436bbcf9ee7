#pragma once

#include <string>
#include <vector>

#include <cairn/multibody/model.h>

namespace cairn::multibody {

/// The DC drive of one joint, for the electrical energy of thesis eq. 2.6: the motor current is
/// I = tau / (gear_ratio * torque_constant) and the armature losses R I^2. A joint without a drive has
/// torque_constant 0 and contributes only its mechanical power |tau omega|.
struct JointDrive {
  /// Armature (terminal) resistance R (ohm).
  double resistance = 0.0;
  /// Motor torque constant K_tau (N m / A); 0: the joint has no drive data.
  double torque_constant = 0.0;
  /// Gear reduction ratio r.
  double gear_ratio = 1.0;
};

/// The drives per velocity coordinate of `model` from the `motors` mapping of a walking-model YAML
/// (data/robots/cairn_humanoid_walking.yaml): each key is a joint name without its side prefix ("knee" for
/// l_knee and r_knee) with {resistance, torque_constant, gear_ratio}; joints without an entry get no drive.
/// Throws std::invalid_argument naming the file, the line and the key on a missing or non-positive value or a key
/// that matches no joint.
std::vector<JointDrive> LoadJointDrives(const Model& model, const std::string& walking_yaml_path);

}  // namespace cairn::multibody
