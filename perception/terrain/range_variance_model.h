#pragma once

/// @file
/// RangeVarianceModel: the depth sensor's noise as a function of ray length.

namespace cairn::perception {

/// The standard deviation of a depth measurement as a quadratic of its ray length z, the usual structured-light
/// fit σ(z) = a + b (z − c)²; the defaults are the published Intel RealSense D435 values (seed 001 uses this
/// sensor; its §4.2 only says that the variance grows with ray length). Elevation fusion uses σ(z)² as the
/// measurement variance of a point's height.
struct RangeVarianceModel {
  /// σ at the sweet spot c, metres.
  double a{0.0024};
  /// Curvature, 1/m.
  double b{0.0066};
  /// Ray length of the smallest noise, metres.
  double c{0.77};

  /// σ(z) in metres.
  double StdDev(double z) const { return a + b * (z - c) * (z - c); }
  /// σ(z)², m².
  double Variance(double z) const {
    const double s = StdDev(z);
    return s * s;
  }
  /// Throws std::invalid_argument unless a > 0 and b >= 0 and all are finite (σ must be positive at every range,
  /// or the Kalman update would divide by zero), naming the bad coefficient.
  void Validate() const;
};

}  // namespace cairn::perception
