#pragma once

#include <stdexcept>
#include <string>

namespace cairn::cli {

/// A mistake in the command line itself (a value out of its option's range, options that contradict each other):
/// main() prints its message on one line and exits with 2, as for CLI11's own parse errors, whether it is thrown
/// while the options are parsed or later by a command's action. Failures that depend on files or data are other
/// std::exception types (exit 1).
class UsageError : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

}  // namespace cairn::cli
