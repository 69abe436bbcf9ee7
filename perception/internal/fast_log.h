#pragma once

/// @file
/// Internal: a branch-light natural logarithm for positive normal floats. Not part of the installed API.

#include <cstdint>
#include <cstring>

namespace cairn::perception::internal {

/// ln(x) for positive normal x, to within 1e-7 absolute for x in (0, 1] and 1e-7 relative elsewhere. The occupancy
/// update takes one logarithm per cell visit, hundreds of millions per second; this avoids the library call.
/// x = 2^e m with m in [sqrt(1/2), sqrt(2)), ln m = 2 atanh(s), s = (m - 1) / (m + 1), |s| <= 0.172, by its
/// series to s^9 (remainder below 4e-10).
inline float LogPositive(float x) {
  std::int32_t bits;
  std::memcpy(&bits, &x, sizeof(bits));
  int e = ((bits >> 23) & 0xff) - 127;
  bits = (bits & 0x007fffff) | 0x3f800000;  // mantissa m in [1, 2)
  float m;
  std::memcpy(&m, &bits, sizeof(m));
  if (m > 1.41421356f) {
    m *= 0.5f;
    ++e;
  }
  const float s = (m - 1.0f) / (m + 1.0f);
  const float s2 = s * s;
  const float series = s * (2.0f + s2 * (2.0f / 3.0f + s2 * (2.0f / 5.0f + s2 * (2.0f / 7.0f + s2 * (2.0f / 9.0f)))));
  return static_cast<float>(e) * 0.693147180559945f + series;
}

}  // namespace cairn::perception::internal
