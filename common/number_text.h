#pragma once

/// @file
/// Numbers as text for messages and files, the same way everywhere.

#include <string>

namespace cairn {

/// `x` with the fewest digits that read back as the same double ("%.17g"), for files that must round-trip.
std::string FormatExact(double x);

/// `x` with six significant digits ("%g"), for error messages and reports.
std::string FormatShort(double x);

}  // namespace cairn
