#include "cairn/common/number_text.h"

#include <cstdio>

namespace cairn {

std::string FormatExact(double x) {
  char text[32];
  std::snprintf(text, sizeof(text), "%.17g", x);
  return text;
}

std::string FormatShort(double x) {
  char text[32];
  std::snprintf(text, sizeof(text), "%g", x);
  return text;
}

// 64-bit integers need at most 20 digits and a sign.
std::string FormatShort(int x) { return FormatShort(static_cast<long long>(x)); }
std::string FormatShort(long x) { return FormatShort(static_cast<long long>(x)); }
std::string FormatShort(long long x) {
  char text[32];
  std::snprintf(text, sizeof(text), "%lld", x);
  return text;
}
std::string FormatShort(unsigned x) { return FormatShort(static_cast<unsigned long long>(x)); }
std::string FormatShort(unsigned long x) { return FormatShort(static_cast<unsigned long long>(x)); }
std::string FormatShort(unsigned long long x) {
  char text[32];
  std::snprintf(text, sizeof(text), "%llu", x);
  return text;
}

}  // namespace cairn
