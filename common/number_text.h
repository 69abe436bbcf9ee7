#pragma once

/// @file
/// Numbers as text for messages and files, the same way everywhere.

#include <string>

namespace cairn {

/// `x` with enough digits to read back as the same double ("%.17g"), for files that must round-trip.
std::string FormatExact(double x);

/// `x` with six significant digits ("%g"), for error messages and reports.
std::string FormatShort(double x);

/// @name Integers, exactly
/// Every digit of an integer ("%d"-style, never an exponent), so that a count or an index in a message reads
/// the same whatever its size: FormatShort(1234567) is "1234567" where the double overload would give
/// "1.23457e+06". One overload per standard integer type so that no integer argument is converted to double.
/// (Other integer types, such as short or char, promote to int.)
///@{
std::string FormatShort(int x);
std::string FormatShort(long x);
std::string FormatShort(long long x);
std::string FormatShort(unsigned x);
std::string FormatShort(unsigned long x);
std::string FormatShort(unsigned long long x);
///@}

}  // namespace cairn
