#pragma once

/// @file
/// Internal: an exp() for non-positive float arguments that compilers vectorise. Not part of the installed API.

#include <cstdint>
#include <cstring>

namespace cairn::perception::internal {

/// e^x for x <= 0, to within 2e-7 relative error; arguments below -87 (and NaN) give e^-87 ~ 1.6e-38, which the
/// callers mask or treat as zero. std::exp is a library call per element, which keeps loops scalar; this is
/// branch-free so that `#pragma omp simd` loops over it vectorise. Range reduction x = n ln2 + r, |r| <= ln2/2,
/// then a degree-6 Taylor polynomial (remainder |r|^7/7! < 1.3e-7) and 2^n built in the exponent bits.
inline float ExpNonPositive(float x) {
  x = x > -87.0f ? x : -87.0f;
  x = x < 0.0f ? x : 0.0f;
  // Round to nearest for a non-positive argument: truncation of t - 0.5 rounds towards zero, i.e. up.
  const int n = static_cast<int>(x * 1.44269504088896341f - 0.5f);
  const float fn = static_cast<float>(n);
  const float r = (x - fn * 0.693145751953125f) - fn * 1.428606765330187e-06f;
  float p = 1.0f / 720.0f;
  p = p * r + 1.0f / 120.0f;
  p = p * r + 1.0f / 24.0f;
  p = p * r + 1.0f / 6.0f;
  p = p * r + 0.5f;
  p = p * r + 1.0f;
  p = p * r + 1.0f;
  const std::int32_t bits = (n + 127) << 23;
  float scale;
  std::memcpy(&scale, &bits, sizeof(scale));
  return p * scale;
}

}  // namespace cairn::perception::internal
