#pragma once

/// @file
/// Checks of the files named on the command line, made before any work so that the message names the option
/// and the file in plain words (instead of a decoder's or stream's text, or after a long computation).

#include <string>

namespace cairn::cli {

/// Throws std::runtime_error (exit 1) unless `path`, given for `option`, is an existing readable file: says that
/// it does not exist, is a folder, or cannot be read and why. `kind` names what is expected, e.g. "an image file".
void CheckInputFile(const std::string& option, const std::string& path, const std::string& kind);

/// Throws std::runtime_error (exit 1) unless a file can be written at `path`, given for `option`: `path` is not a
/// folder and its parent folder exists and is writable. (The write itself may still fail, e.g. on a full disk.)
void CheckOutputFile(const std::string& option, const std::string& path);

}  // namespace cairn::cli
