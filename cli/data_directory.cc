#include "data_directory.h"

#include <filesystem>
#include <system_error>

namespace cairn::cli {

std::string DataDirectory() {
  namespace fs = std::filesystem;
  std::error_code error;
  const fs::path executable = fs::read_symlink("/proc/self/exe", error);
  if (!error) {
    // A marker file rather than the folder alone: an unrelated share/cairn (another version's) must not be taken.
    const fs::path installed = (executable.parent_path() / CAIRN_INSTALLED_DATA_RELATIVE).lexically_normal();
    if (fs::is_regular_file(installed / "robots" / "cairn_humanoid_walking.yaml", error)) return installed.string();
  }
  return CAIRN_SOURCE_DATA_DIR;
}

}  // namespace cairn::cli
