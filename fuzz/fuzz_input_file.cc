#include "fuzz_input_file.h"

#include <unistd.h>

#include <atomic>
#include <cstdio>
#include <filesystem>
#include <stdexcept>
#include <system_error>

#include "cairn/common/number_text.h"

namespace cairn::fuzz {
namespace {

namespace fs = std::filesystem;

fs::path ScratchRoot() {
  std::error_code error;
  if (fs::is_directory("/dev/shm", error)) return "/dev/shm";
  return fs::temp_directory_path();
}

}  // namespace

FuzzInputFile::FuzzInputFile(const std::string& name) {
  static std::atomic<int> counter{0};
  const fs::path folder = ScratchRoot() / ("cairn-fuzz-" + cairn::FormatShort(::getpid()) + "-" +
                                           cairn::FormatShort(counter.fetch_add(1)));
  std::error_code error;
  fs::remove_all(folder, error);
  if (!fs::create_directories(folder, error)) {
    throw std::runtime_error("FuzzInputFile: cannot create the scratch folder '" + folder.string() +
                             "': " + error.message());
  }
  folder_ = folder.string();
  path_ = (folder / name).string();
}

FuzzInputFile::~FuzzInputFile() {
  std::error_code ignored;
  fs::remove_all(folder_, ignored);
}

void FuzzInputFile::Link(const std::string& link_name, const std::string& target) const {
  std::error_code error;
  fs::create_symlink(target, fs::path(folder_) / link_name, error);
  if (error) {
    throw std::runtime_error("FuzzInputFile: cannot link '" + link_name + "' to '" + target + "' in '" + folder_ +
                             "': " + error.message());
  }
}

const std::string& FuzzInputFile::Write(std::string_view bytes) const {
  // A plain rewrite, not WriteFileAtomically: only this process reads the file, after this call returns.
  std::FILE* file = std::fopen(path_.c_str(), "wb");
  bool ok = file != nullptr;
  if (ok && !bytes.empty()) ok = std::fwrite(bytes.data(), 1, bytes.size(), file) == bytes.size();
  if (file != nullptr && std::fclose(file) != 0) ok = false;
  if (!ok) throw std::runtime_error("FuzzInputFile: cannot write '" + path_ + "'.");
  return path_;
}

}  // namespace cairn::fuzz
