#pragma once

// Minimal JSON text helpers for the commands' --json output (flat objects and arrays written by hand).

#include <cmath>
#include <cstdio>
#include <string>

namespace cairn::cli {

/// `text` as a JSON string literal.
inline std::string JsonString(const std::string& text) {
  std::string out = "\"";
  for (const char c : text) {
    if (c == '"' || c == '\\') {
      out += '\\';
      out += c;
    } else if (c == '\n') {
      out += "\\n";
    } else if (static_cast<unsigned char>(c) < 0x20) {
      char escaped[8];
      std::snprintf(escaped, sizeof(escaped), "\\u%04x", c);
      out += escaped;
    } else {
      out += c;
    }
  }
  return out + "\"";
}

/// A number with `digits` significant digits; JSON has no infinity or NaN, so those become null.
inline std::string JsonNumber(double value, int digits = 6) {
  if (!std::isfinite(value)) return "null";
  char text[40];
  std::snprintf(text, sizeof(text), "%.*g", digits, value);
  return text;
}

inline const char* JsonBool(bool value) { return value ? "true" : "false"; }

}  // namespace cairn::cli
