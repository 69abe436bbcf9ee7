#pragma once

/// @file
/// The one-dimensional Kalman update of a map cell (seed 001, eq. 1).

#include <cmath>

namespace cairn::perception {

/// Fuses a measurement `z` of variance `measurement_variance` into a cell estimated as N(*mean, *variance)
/// (seed 001, eq. 1, after Cremean and Murray 2005):
///   mean' = (var_m * mean + var * z) / (var + var_m),   var' = var * var_m / (var + var_m).
/// An unknown cell (mean NaN) takes the measurement as it is. Fusing n measurements of equal variance s² into an
/// unknown cell gives their average with variance s² / n. The caller guarantees a finite z and a positive,
/// finite measurement variance (the map builders check their inputs once rather than per cell).
inline void KalmanCellUpdate(double z, double measurement_variance, double* mean, double* variance) {
  if (std::isnan(*mean) || !(*variance > 0.0)) {
    *mean = z;
    *variance = measurement_variance;
    return;
  }
  const double sum = *variance + measurement_variance;
  *mean = (measurement_variance * *mean + *variance * z) / sum;
  *variance = *variance * measurement_variance / sum;
}

}  // namespace cairn::perception
