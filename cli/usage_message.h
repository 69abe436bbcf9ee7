#pragma once

#include <string>

#include <CLI/CLI.hpp>

namespace cairn::cli {

/// One clear line for a CLI11 parse error raised while parsing `app` (the chosen subcommand, or the top-level
/// program): a repeated option says so (CLI11: "At Most 1 required but received 2"), an unknown option is named
/// with the closest known one, a missing value or a stray argument is named. Other errors keep CLI11's text.
std::string UsageMessage(const CLI::ParseError& error, const CLI::App& app);

}  // namespace cairn::cli
