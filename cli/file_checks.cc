#include "file_checks.h"

#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <stdexcept>

namespace cairn::cli {

void CheckInputFile(const std::string& option, const std::string& path, const std::string& kind) {
  const std::string what = option + " '" + path + "'";
  if (path.empty()) throw std::runtime_error(option + " is empty; give " + kind);
  struct stat info {};
  if (::stat(path.c_str(), &info) != 0) {
    const int error = errno;
    if (error == ENOENT || error == ENOTDIR) throw std::runtime_error(what + " does not exist; give " + kind);
    throw std::runtime_error(what + " cannot be read (" + std::strerror(error) + ")");
  }
  if (S_ISDIR(info.st_mode)) throw std::runtime_error(what + " is a folder; give " + kind);
  if (::access(path.c_str(), R_OK) != 0) {
    const int error = errno;
    throw std::runtime_error(what + " cannot be read (" + std::strerror(error) + ")");
  }
}

void CheckOutputFile(const std::string& option, const std::string& path) {
  const std::string what = option + " '" + path + "'";
  if (path.empty()) throw std::runtime_error(option + " is empty; give a file name");
  struct stat info {};
  if (::stat(path.c_str(), &info) == 0 && S_ISDIR(info.st_mode)) {
    throw std::runtime_error(what + " is a folder; give a file name");
  }
  std::string parent = std::filesystem::path(path).parent_path().string();
  if (parent.empty()) parent = ".";
  if (::stat(parent.c_str(), &info) != 0) {
    const int error = errno;
    throw std::runtime_error(what + " cannot be written: its folder '" + parent + "' " +
                             (error == ENOENT    ? std::string("does not exist")
                              : error == ENOTDIR ? std::string("is not a folder")
                                                 : std::string("cannot be used (") + std::strerror(error) + ")"));
  }
  if (!S_ISDIR(info.st_mode)) {
    throw std::runtime_error(what + " cannot be written: '" + parent + "' is not a folder");
  }
  if (::access(parent.c_str(), W_OK) != 0) {
    const int error = errno;
    throw std::runtime_error(what + " cannot be written: its folder '" + parent + "' is not writable (" +
                             std::strerror(error) + ")");
  }
}

}  // namespace cairn::cli
