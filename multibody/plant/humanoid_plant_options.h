#pragma once

#include <string>
#include <vector>

#include <cairn/multibody/plant/bullet_plant_options.h>
#include <cairn/multibody/plant/contact_monitor_options.h>
#include <cairn/multibody/plant/joint_drive.h>

namespace cairn::multibody {

/// How a HumanoidPlant is built, besides its model, terrain and PD controller.
struct HumanoidPlantOptions {
  /// Step, contact and solver settings of the Bullet world; the plant's periodic update runs every time_step.
  BulletPlantOptions bullet;
  /// Slip, load and fall thresholds.
  ContactMonitorOptions monitor;
  /// Left and right sole bodies (or links).
  std::vector<std::string> sole_bodies{"l_sole", "r_sole"};
  /// The base body whose height and tilt decide a fall.
  std::string base_body = "pelvis";
  /// Drives per velocity coordinate for E_ele (empty: E_ele stays 0); see LoadJointDrives.
  std::vector<JointDrive> drives;
  /// Declare the `torque` input (a feedforward torque added to the PD torque before saturation).
  bool torque_input = false;
  /// End the simulation (EventStatus::ReachedTermination) when a fall is detected.
  bool stop_on_fall = true;
};

}  // namespace cairn::multibody
