#pragma once

/// @file
/// Internal: a branch-light natural logarithm for positive normal floats. Not part of the installed API.

#include <cstdint>
#include <cstring>

namespace cairn::perception::internal {

/// ln(x) for positive normal x, to within 1e-7 absolute for x in (0, 1] and 1e-7 relative elsewhere. The occupancy
/// update takes tens of millions of logarithms per frame (one per disparity sample of every ray); this avoids the
/// library call and vectorises.
/// x = 2^e m with m in [sqrt(1/2), sqrt(2)), ln m = 2 atanh(s), s = (m - 1) / (m + 1), |s| <= 0.172, by its
/// series to s^9 (remainder below 4e-10).
inline float LogPositive(float x) {
  std::int32_t bits;
  std::memcpy(&bits, &x, sizeof(bits));
  // m = 1.mantissa in [1, 2), halved (exponent one lower) when above sqrt(2): both decided on the integer bits, so
  // the function has no floating-point comparison or conditional operation and loops calling it vectorise (GCC
  // does not if-convert those under the default -ftrapping-math).
  const std::int32_t mantissa = bits & 0x007fffff;
  const std::int32_t above = mantissa > 0x003504f3 ? 1 : 0;  // 0x3fb504f3 is 1.41421356f
  const std::int32_t e = ((bits >> 23) & 0xff) - 127 + above;
  bits = mantissa | (above != 0 ? 0x3f000000 : 0x3f800000);
  float m;
  std::memcpy(&m, &bits, sizeof(m));
  const float s = (m - 1.0f) / (m + 1.0f);
  const float s2 = s * s;
  const float series = s * (2.0f + s2 * (2.0f / 3.0f + s2 * (2.0f / 5.0f + s2 * (2.0f / 7.0f + s2 * (2.0f / 9.0f)))));
  return static_cast<float>(e) * 0.693147180559945f + series;
}

}  // namespace cairn::perception::internal
