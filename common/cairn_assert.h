#pragma once

/// @file
/// Always-on checks of internal invariants. A failed check is a bug in Cairn, not a user error: user mistakes
/// throw std::invalid_argument / std::runtime_error with a message that suggests the fix.

namespace cairn::internal {

/// Throws std::logic_error naming the failed condition and its place in the source.
[[noreturn]] void AssertionFailed(const char* condition, const char* function, const char* file, int line);

}  // namespace cairn::internal

/// Checks `condition` in every build type (it does not depend on NDEBUG).
#define CAIRN_CHECK(condition)                                                             \
  do {                                                                                     \
    if (!(condition)) ::cairn::internal::AssertionFailed(#condition, __func__, __FILE__, __LINE__); \
  } while (0)
