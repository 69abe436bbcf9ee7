#include "number_range.h"

#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "cairn/common/number_text.h"

namespace cairn::cli {
namespace {

std::string Bound(double x, bool integer) {
  if (!integer) return FormatShort(x);
  char text[32];
  std::snprintf(text, sizeof(text), "%.0f", x);
  return text;
}

}  // namespace

NumberRange::NumberRange(double lower, bool lower_open, double upper, bool upper_open)
    : lower_(lower), lower_open_(lower_open), upper_(upper), upper_open_(upper_open) {
  if (!std::isfinite(lower) || !std::isfinite(upper) || !(lower < upper)) {
    throw std::logic_error("NumberRange: the bounds must be finite with lower < upper; got " + FormatShort(lower) +
                           " and " + FormatShort(upper));
  }
}

NumberRange NumberRange::Closed(double lower, double upper) { return NumberRange(lower, false, upper, false); }

NumberRange NumberRange::AboveAtMost(double lower, double upper) { return NumberRange(lower, true, upper, false); }

NumberRange NumberRange::Open(double lower, double upper) { return NumberRange(lower, true, upper, true); }

NumberRange NumberRange::OddOnly() const {
  NumberRange odd = *this;
  odd.odd_only_ = true;
  return odd;
}

bool NumberRange::Contains(double x) const {
  if (!std::isfinite(x)) return false;
  if (lower_open_ ? !(x > lower_) : !(x >= lower_)) return false;
  if (upper_open_ ? !(x < upper_) : !(x <= upper_)) return false;
  return !odd_only_ || (x == std::floor(x) && std::fmod(std::fabs(x), 2.0) == 1.0);
}

std::string NumberRange::Describe(bool integer) const {
  const std::string kind = odd_only_ ? "an odd integer" : integer ? "an integer" : "a number";
  const std::string lo = Bound(lower_, integer), hi = Bound(upper_, integer);
  if (!lower_open_ && !upper_open_) return kind + " from " + lo + " to " + hi;
  return kind + (lower_open_ ? " greater than " : " at least ") + lo +
         (upper_open_ ? " and less than " : " and at most ") + hi;
}

}  // namespace cairn::cli
