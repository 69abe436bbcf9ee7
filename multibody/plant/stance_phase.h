#pragma once

namespace cairn::multibody {

/// One stance of a sole: from the step it became loaded to the last step it was loaded before staying unloaded
/// for longer than ContactMonitorOptions::stance_gap, with its required coefficient of friction (thesis eq. 2.2: the
/// largest |F_t / F_n| while loaded) read three ways. A sole lands with some speed, so friction stops it by an
/// impulse at its limit in the first milliseconds (rcof is then the terrain's mu); in double support the two soles
/// also push against each other. The planner's model predicts neither: it predicts the ratio of the net ground
/// force that accelerates the COM, which net_rcof measures.
struct StancePhase {
  /// 0 for the first (left) sole, 1 for the second (right).
  int foot = 0;
  /// First loaded time (s).
  double start = 0.0;
  /// Last loaded time (s); for a stance still going on, the latest time.
  double end = 0.0;
  /// max |F_t / F_n| of this sole over the stance.
  double rcof = 0.0;
  /// The same after the first ContactMonitorOptions::touchdown_time of the stance (0 for a shorter stance).
  double rcof_after_touchdown = 0.0;
  /// max over the stance of |F_t / F_n| of the net force of both soles, low-passed with the time constant
  /// ContactMonitorOptions::force_filter_time: the quantity the planner's RCOF model predicts.
  double net_rcof = 0.0;
  /// False while the stance goes on (loaded, or unloaded for at most ContactMonitorOptions::stance_gap).
  bool finished = false;
};

}  // namespace cairn::multibody
