#include "cairn/common/atomic_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <stdexcept>
#include <vector>

namespace cairn {
namespace {

[[noreturn]] void Fail(const std::string& what, const std::string& path, int error) {
  const bool folder_problem =
      error == ENOENT || error == ENOTDIR || error == EACCES || error == EPERM || error == EROFS;
  throw std::runtime_error("Cannot write '" + path + "': " + what + " failed (" + std::strerror(error) + ")." +
                           (folder_problem ? " Check that the folder exists and is writable." : ""));
}

}  // namespace

void WriteFileAtomically(const std::string& path, const std::string& contents) {
  if (path.empty()) throw std::runtime_error("Cannot write a file with an empty name; give a file name.");
  struct stat existing {};
  if (::stat(path.c_str(), &existing) == 0 && S_ISDIR(existing.st_mode)) {
    throw std::runtime_error("Cannot write '" + path + "': it is a folder; give a file name.");
  }
  std::string pattern = path + ".tmp.XXXXXX";
  std::vector<char> buffer(pattern.begin(), pattern.end());
  buffer.push_back('\0');
  const int fd = ::mkstemp(buffer.data());
  if (fd < 0) Fail("creating a temporary file", path, errno);
  const std::string temporary(buffer.data());
  auto cleanup_and_fail = [&](const std::string& what) {
    const int error = errno;
    ::close(fd);
    ::unlink(temporary.c_str());
    Fail(what, path, error);
  };
  std::size_t written = 0;
  while (written < contents.size()) {
    const ssize_t n = ::write(fd, contents.data() + written, contents.size() - written);
    if (n < 0) {
      if (errno == EINTR) continue;
      cleanup_and_fail("writing");
    }
    written += static_cast<std::size_t>(n);
  }
  // mkstemp creates 0600; give the file the usual permissions (subject to the umask).
  const mode_t mask = ::umask(0);
  ::umask(mask);
  if (::fchmod(fd, 0666 & ~mask) != 0) cleanup_and_fail("setting permissions");
  if (::fsync(fd) != 0) cleanup_and_fail("flushing");
  if (::close(fd) != 0) {
    const int error = errno;
    ::unlink(temporary.c_str());
    Fail("closing", path, error);
  }
  if (std::rename(temporary.c_str(), path.c_str()) != 0) {
    const int error = errno;
    ::unlink(temporary.c_str());
    Fail("renaming the temporary file", path, error);
  }
}

}  // namespace cairn
