#pragma once

/// @file
/// The one way the `cairn` subcommands declare numeric options: every value is parsed strictly (decimal text
/// only, the whole text), must be finite, an integer where the type is one, and inside a stated NumberRange.
/// Anything else is a usage error (UsageError, exit 2) with one line naming the option, the text given and the
/// range, e.g. "--duration 'abc' is not a number; give a number greater than 0 and at most 10000".

#include <string>

#include <CLI/CLI.hpp>

#include "number_range.h"

namespace cairn::cli {

/// Parses `text`, given for `option`, as a T (double, int, unsigned or long long) in `range`. Throws UsageError
/// saying whether the text is not a number, not finite (nan, inf), not an integer, or out of range.
template <typename T>
T ParseNumber(const std::string& option, const std::string& text, const NumberRange& range);

/// Declares the option `name` (e.g. "--duration") on `app`, storing the parsed value in `*value` when given
/// (`*value` keeps its default otherwise). --help shows `description`, the range and the default.
template <typename T>
CLI::Option* AddNumberOption(CLI::App& app, const std::string& name, T* value, const std::string& description,
                             const NumberRange& range);

}  // namespace cairn::cli
