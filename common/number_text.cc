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

}  // namespace cairn
