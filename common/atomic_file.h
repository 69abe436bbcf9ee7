#pragma once

#include <string>

namespace cairn {

/// Writes `contents` to `path` atomically: into a temporary file in the same folder, flushed, then renamed over
/// `path`. Readers see either the old file or the whole new one, never a partial write. Throws
/// std::runtime_error naming the path and the system's reason on failure (the temporary file is removed), or
/// saying so when `path` is an existing folder or empty.
void WriteFileAtomically(const std::string& path, const std::string& contents);

}  // namespace cairn
