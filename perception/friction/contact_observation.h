#pragma once

namespace cairn::perception {

/// What a contact taught about the friction of the surface under it (learning from touch).
struct ContactObservation {
  enum class Kind {
    kMeasured,  ///< A measured coefficient (probe, or a foot pulled until it slid), with its measurement noise.
    kSlipped,   ///< The foot slipped while using a coefficient `value`: μ < value (censored).
    kHeld,      ///< The foot held while using a coefficient `value`: μ >= value (censored).
  };
  Kind kind{Kind::kMeasured};
  double value{0.0};
  /// Measurement noise of kMeasured observations (> 0).
  double stddev{0.05};

  static ContactObservation Measured(double mu, double stddev) { return {Kind::kMeasured, mu, stddev}; }
  static ContactObservation Slipped(double required) { return {Kind::kSlipped, required, 0.0}; }
  static ContactObservation Held(double required) { return {Kind::kHeld, required, 0.0}; }
};

}  // namespace cairn::perception
