#pragma once

/// @file
/// The four classes of a traversability value (seed 001 §4.1).

#include <string>

namespace cairn::perception {

/// Classes of a traversability value t in [0, 1] (seed 001 §4.1): 1 traversable, (0.5, 1) semi-traversable,
/// (0, 0.5] semi-untraversable, 0 untraversable.
enum class TraversabilityClass { kUnknown, kUntraversable, kSemiUntraversable, kSemiTraversable, kTraversable };

/// The class of t; NaN (no information) is kUnknown.
inline TraversabilityClass ClassifyTraversability(double t) {
  if (!(t == t)) return TraversabilityClass::kUnknown;
  if (t >= 1.0) return TraversabilityClass::kTraversable;
  if (t > 0.5) return TraversabilityClass::kSemiTraversable;
  if (t > 0.0) return TraversabilityClass::kSemiUntraversable;
  return TraversabilityClass::kUntraversable;
}

/// "traversable", "semi-traversable", "semi-untraversable", "untraversable" or "unknown".
inline std::string TraversabilityClassName(TraversabilityClass c) {
  switch (c) {
    case TraversabilityClass::kTraversable: return "traversable";
    case TraversabilityClass::kSemiTraversable: return "semi-traversable";
    case TraversabilityClass::kSemiUntraversable: return "semi-untraversable";
    case TraversabilityClass::kUntraversable: return "untraversable";
    case TraversabilityClass::kUnknown: break;
  }
  return "unknown";
}

}  // namespace cairn::perception
