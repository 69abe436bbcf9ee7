#pragma once

namespace cairn::multibody {

/// Thresholds of ContactMonitor: when a sole counts as loaded, when it slips, when the robot has fallen.
struct ContactMonitorOptions {
  /// A sole is loaded while its normal force exceeds this (N): 3 % of the 64 kg humanoid's weight, above the
  /// solver noise of a sole hovering in contact and below the load of any real stance.
  double loaded_force = 20.0;
  /// A loaded sole slides while the tangential speed of its frame exceeds this (m/s).
  double slip_speed = 0.01;
  /// A slip event is reported once a loaded sole has slid this far (m) in one continuous slide, so that the
  /// micro-motion of a settling contact is not a slip.
  double slip_distance = 0.002;
  /// A stance goes on through unloaded spells shorter than this (s), so that a sole chattering for a few
  /// milliseconds as it lands (measured: up to 60 ms of 1-3 ms contacts) makes one stance, not dozens. In [0, 1].
  double stance_gap = 0.03;
  /// StancePhase::rcof_after_touchdown leaves out the first this of a stance (s): the impact of landing. In [0, 1].
  double touchdown_time = 0.05;
  /// Time constant of the first-order low-pass on the soles' net force behind StancePhase::net_rcof (s; a 16 Hz
  /// cut-off at 0.01, as gait laboratories low-pass force plates; 0: unfiltered). >= 0.
  double force_filter_time = 0.01;
  /// Fallen when the base origin is less than this (m) above the lower sole frame (the humanoid stands at 0.86 m).
  double fall_base_height = 0.5;
  /// Fallen when the base's z axis tilts more than this (rad, 40 deg) from the world's.
  double fall_tilt = 0.7;
  /// Fallen when a body other than the feet presses on the terrain with more than this (N).
  double fall_contact_force = 1.0;
};

}  // namespace cairn::multibody
