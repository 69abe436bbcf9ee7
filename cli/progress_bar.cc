#include "progress_bar.h"

#include <unistd.h>

#include <utility>

namespace cairn::cli {

ProgressBar::ProgressBar(std::string label, std::FILE* out, bool interactive)
    : label_(std::move(label)), out_(out), interactive_(interactive) {}

ProgressBar ProgressBar::ForStderr(std::string label) {
  return ProgressBar(std::move(label), stderr, ::isatty(STDERR_FILENO) == 1);
}

void ProgressBar::Update(std::size_t done, std::size_t total) {
  if (finished_) return;
  const bool end = done >= total;
  if (!interactive_) {
    if (!started_) std::fprintf(out_, "%s: started, %zu to do\n", label_.c_str(), total);
    if (end) std::fprintf(out_, "%s: done, %zu of %zu\n", label_.c_str(), done, total);
  } else {
    const int percent = total == 0 ? 100 : static_cast<int>(100 * done / total);
    if (percent != last_percent_ || end) {
      last_percent_ = percent;
      const int filled = percent / 4;
      std::fprintf(out_, "\r%s [%s%s] %3d%% (%zu/%zu)%s", label_.c_str(), std::string(filled, '#').c_str(),
                   std::string(25 - filled, ' ').c_str(), percent, done, total, end ? "\n" : "");
    }
  }
  started_ = true;
  finished_ = end;
  std::fflush(out_);
}

}  // namespace cairn::cli
