#pragma once

#include <cstddef>
#include <cstdio>
#include <string>

namespace cairn::cli {

/// Progress of a long computation on a stream (stderr). On a terminal it is one line redrawn in place at each
/// whole percent; elsewhere (stderr redirected to a file or a pipe) redraws would pile up as kilobytes of
/// carriage returns, so it writes only a line when the work starts and one when it ends.
class ProgressBar {
 public:
  /// `interactive`: redraw in place (see the class comment); ForStderr() decides it with isatty().
  ProgressBar(std::string label, std::FILE* out, bool interactive);

  /// A bar on stderr, interactive if stderr is a terminal.
  static ProgressBar ForStderr(std::string label);

  /// Reports `done` of `total` units; the end line is written when done reaches total.
  void Update(std::size_t done, std::size_t total);

  bool interactive() const { return interactive_; }

 private:
  std::string label_;
  std::FILE* out_;
  bool interactive_;
  bool started_{false};
  bool finished_{false};
  int last_percent_{-1};
};

}  // namespace cairn::cli
