#include "cairn/common/atomic_output_directory.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <stdexcept>
#include <system_error>
#include <utility>
#include <vector>

#include "cairn/common/atomic_file.h"

namespace cairn {
namespace {

namespace fs = std::filesystem;

[[noreturn]] void Fail(const std::string& path, const std::string& reason) {
  throw std::runtime_error("Cannot write the folder '" + path + "': " + reason);
}

// A name WriteFileAtomically leaves behind when killed mid-write ("<name>.tmp.XXXXXX") belongs to `name`'s owner.
bool Owned(const std::string& name, const AtomicOutputDirectory::OwnsName& owns) {
  if (owns(name)) return true;
  const std::size_t at = name.rfind(".tmp.");
  return at != std::string::npos && at > 0 && name.size() == at + 11 && owns(name.substr(0, at));
}

// mkdtemp on "<folder>/<prefix>XXXXXX"; returns the created path or sets errno and returns "".
std::string MakeTemporaryFolder(const fs::path& folder, const std::string& prefix) {
  std::string pattern = (folder / (prefix + "XXXXXX")).string();
  std::vector<char> buffer(pattern.begin(), pattern.end());
  buffer.push_back('\0');
  if (::mkdtemp(buffer.data()) == nullptr) return "";
  return buffer.data();
}

// Flushes a folder's entries to disk so that a rename of or within it survives a crash. Best effort: a file
// system that cannot sync folders still renames correctly.
void SyncFolder(const std::string& folder) {
  const int fd = ::open(folder.c_str(), O_RDONLY | O_DIRECTORY);
  if (fd < 0) return;
  ::fsync(fd);
  ::close(fd);
}

// True if `inner` is `outer` or inside it (both absolute and normalised).
bool IsWithin(const fs::path& inner, const fs::path& outer) {
  auto i = inner.begin();
  for (auto o = outer.begin(); o != outer.end(); ++o, ++i) {
    if (o->empty()) continue;  // the trailing "" of a path ending in a separator
    if (i == inner.end() || *i != *o) return false;
  }
  return true;
}

// Exchanges two folders atomically; false with errno set if that failed or is unsupported.
bool ExchangeFolders(const std::string& a, const std::string& b) {
#ifdef RENAME_EXCHANGE
  return ::renameat2(AT_FDCWD, a.c_str(), AT_FDCWD, b.c_str(), RENAME_EXCHANGE) == 0;
#else
  errno = ENOSYS;
  return false;
#endif
}

}  // namespace

AtomicOutputDirectory::AtomicOutputDirectory(const std::string& path, OwnsName owns) : path_(path) {
  if (path.empty()) Fail(path, "the name is empty; give a folder name.");
  std::error_code error;
  // Symbolic links are resolved: the folder a link points to is replaced, and the link kept.
  fs::path target = fs::weakly_canonical(fs::absolute(path, error), error);
  if (error) Fail(path, "the name cannot be resolved (" + error.message() + ").");
  if (!target.has_filename() && target.has_parent_path()) target = target.parent_path();  // "out/" -> "out"
  if (target == target.root_path() || target.filename() == "." || target.filename() == "..") {
    Fail(path, "it is a root folder; give a folder of its own, e.g. 'out'.");
  }
  const fs::path cwd = fs::current_path(error);
  if (!error && IsWithin(fs::weakly_canonical(cwd, error), target)) {
    Fail(path, "it is (or holds) the working folder, which would be replaced as a whole; give a folder of its "
               "own, e.g. 'out'.");
  }
  const fs::file_status status = fs::status(target, error);
  const bool exists = fs::exists(status);
  mode_t mode = 0;
  if (exists) {
    if (!fs::is_directory(status)) Fail(path, "it exists and is not a folder.");
    for (const fs::directory_entry& entry : fs::directory_iterator(target, error)) {
      const std::string name = entry.path().filename().string();
      std::error_code entry_error;
      if (!entry.is_regular_file(entry_error) || !Owned(name, owns)) {
        Fail(path, "it holds '" + name +
                       "', which this command does not write, and the folder is replaced as a whole; give a new or "
                       "empty folder, or move '" + name + "' away.");
      }
    }
    if (error) Fail(path, "its files cannot be listed (" + error.message() + ").");
    struct stat info {};
    if (::stat(target.c_str(), &info) == 0) mode = info.st_mode & 07777;
  } else {
    const mode_t mask = ::umask(0);
    ::umask(mask);
    mode = 0777 & ~mask;
  }
  const fs::path parent = target.parent_path();
  fs::create_directories(parent, error);
  if (error) Fail(path, "its parent folder '" + parent.string() + "' cannot be created (" + error.message() + ").");
  staging_ = MakeTemporaryFolder(parent, "." + target.filename().string() + ".cairn-");
  if (staging_.empty()) {
    Fail(path, "a folder cannot be created in '" + parent.string() + "' (" + std::strerror(errno) +
                   "); check that it is a writable folder.");
  }
  ::chmod(staging_.c_str(), mode);  // mkdtemp makes 0700; a failure here only leaves it private
  target_ = target.string();
}

AtomicOutputDirectory::~AtomicOutputDirectory() {
  if (staging_.empty()) return;
  std::error_code ignored;
  fs::remove_all(staging_, ignored);
}

std::string AtomicOutputDirectory::StagedPath(const std::string& name) const {
  if (committed_) throw std::logic_error("AtomicOutputDirectory::StagedPath after Commit()");
  return staging_ + "/" + name;
}

void AtomicOutputDirectory::WriteFile(const std::string& name, const std::string& contents) {
  try {
    WriteFileAtomically(StagedPath(name), contents);
  } catch (const std::runtime_error& error) {
    // Name the file where the user will look for it, not in the hidden staging folder.
    std::string message = error.what();
    for (std::size_t at = message.find(staging_); at != std::string::npos; at = message.find(staging_, at)) {
      message.replace(at, staging_.size(), path_);
      at += path_.size();
    }
    throw std::runtime_error(message);
  }
}

void AtomicOutputDirectory::Commit() {
  if (committed_) throw std::logic_error("AtomicOutputDirectory::Commit called twice");
  SyncFolder(staging_);
  const std::string parent = fs::path(target_).parent_path().string();
  std::error_code error;
  if (fs::exists(fs::symlink_status(target_, error))) {
    const bool exchanged = ExchangeFolders(staging_, target_);
    const int reason = errno;
    if (exchanged) {
      // staging_ now holds the earlier set.
      SyncFolder(parent);
      fs::remove_all(staging_, error);
      staging_.clear();
      committed_ = true;
      return;
    }
    if (reason != EINVAL && reason != ENOSYS && reason != ENOTSUP && reason != ENOENT) {
      Fail(path_, std::string("swapping in the new files failed (") + std::strerror(reason) + ").");
    }
    if (reason != ENOENT) {
      // No atomic exchange on this file system: move the old set aside, then the new one in.
      const std::string old = MakeTemporaryFolder(parent, "." + fs::path(target_).filename().string() + ".cairn-old-");
      if (old.empty() || std::rename(target_.c_str(), old.c_str()) != 0) {
        const int aside = errno;
        if (!old.empty()) ::rmdir(old.c_str());
        Fail(path_, std::string("moving the earlier files aside failed (") + std::strerror(aside) + ").");
      }
      if (std::rename(staging_.c_str(), target_.c_str()) != 0) {
        const int in = errno;
        std::rename(old.c_str(), target_.c_str());  // put the old set back
        Fail(path_, std::string("moving the new files in failed (") + std::strerror(in) + ").");
      }
      SyncFolder(parent);
      staging_.clear();
      committed_ = true;
      fs::remove_all(old, error);
      return;
    }
  }
  if (std::rename(staging_.c_str(), target_.c_str()) != 0) {
    Fail(path_, std::string("moving the new files in failed (") + std::strerror(errno) + ").");
  }
  SyncFolder(parent);
  staging_.clear();
  committed_ = true;
}

}  // namespace cairn
