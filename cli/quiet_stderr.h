#pragma once

namespace cairn::cli {

/// While alive, the process's standard error (file descriptor 2) goes to /dev/null. For calls into image codecs
/// that print their own text (libpng's "libpng error: Read Error", OpenCV's warnings) before reporting failure:
/// the caller reports the failure in one line of its own. Not for use while other threads may write to stderr.
class QuietStderr {
 public:
  QuietStderr();
  ~QuietStderr();
  QuietStderr(const QuietStderr&) = delete;
  QuietStderr& operator=(const QuietStderr&) = delete;

 private:
  int saved_{-1};  // the original stderr, restored on destruction; -1 if silencing failed (stderr left as is)
};

}  // namespace cairn::cli
