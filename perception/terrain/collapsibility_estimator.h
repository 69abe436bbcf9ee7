#pragma once

/// @file
/// CollapsibilityEstimator: the collapsibility of probed ground from the probe's force (seed 001 §5.1, eq. 5).

#include <vector>

namespace cairn::perception {

/// Turns the normal force a probe measures while pushing a predefined depth into the ground into the ground's
/// collapsibility C = max(F_hard − F_ext, 0) / F_hard (seed 001, eq. 5), where F_hard is the force the same push
/// gives on hard reference ground (100 N in the paper). F_ext is the average of the last `window` force samples
/// (the paper averages over a sliding time window against sensor noise). C = 0 is ground at least as stiff as
/// the reference, C = 1 ground that gives no support (a covered hole, deep water). A noisy negative average
/// (a tensile reading) is truncated to C = 1, as the paper truncates C to [0, 1].
class CollapsibilityEstimator {
 public:
  /// Most samples the sliding window may hold.
  static constexpr int kMaxWindow = 1 << 20;

  struct Options {
    /// Reference force on hard ground, N (seed 001 §6: 100 N).
    double hard_force{100.0};
    /// Samples averaged.
    int window{20};
  };

  /// Throws std::invalid_argument for a non-positive or non-finite hard force, or a window outside
  /// [1, kMaxWindow].
  explicit CollapsibilityEstimator(const Options& options);
  CollapsibilityEstimator() : CollapsibilityEstimator(Options{}) {}

  const Options& options() const { return options_; }

  /// Eq. (5) for one force: max(F_hard − F_ext, 0) / F_hard, truncated to at most 1.
  static double FromForce(double force, double hard_force);

  /// Adds a force sample (N); the oldest sample leaves once the window is full. Throws std::invalid_argument for
  /// a non-finite force.
  void AddSample(double force);
  /// Forgets every sample (before the next probe).
  void Reset();
  /// Samples currently in the window.
  int num_samples() const { return count_; }
  /// The window's average force. Throws std::logic_error when there is no sample yet.
  double AverageForce() const;
  /// C from the window's average force. Throws std::logic_error when there is no sample yet.
  double Collapsibility() const;

 private:
  Options options_;
  std::vector<double> ring_;
  int next_{0};
  int count_{0};
};

}  // namespace cairn::perception
