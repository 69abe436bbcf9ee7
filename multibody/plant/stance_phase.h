#pragma once

namespace cairn::multibody {

/// One stance of a sole: from the step it became loaded to the step it was unloaded, with its required
/// coefficient of friction (thesis eq. 2.2: the largest |F_t / F_n| while loaded).
struct StancePhase {
  /// 0 for the first (left) sole, 1 for the second (right).
  int foot = 0;
  /// First loaded time (s).
  double start = 0.0;
  /// Last loaded time (s); for a stance still going on, the latest time.
  double end = 0.0;
  /// max |F_t / F_n| over the stance.
  double rcof = 0.0;
  /// False while the sole is still loaded.
  bool finished = false;
};

}  // namespace cairn::multibody
