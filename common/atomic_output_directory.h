#pragma once

#include <functional>
#include <string>

namespace cairn {

/// A folder of output files replaced as one unit: the old set or the new set is visible, never a mix of the two,
/// never a partial new set, and no file of an earlier, larger set survives next to the new one.
///
/// The files are written into a staging folder next to the final one (`<parent>/.<name>.cairn-XXXXXX`, same
/// file system), and Commit() swaps it in: with one renameat2(RENAME_EXCHANGE) where the file system supports it
/// (the swap is atomic), else with two renames (the final folder is briefly absent between them). The earlier set
/// is then deleted.
///
/// If the process dies before Commit(), the final folder is untouched and a hidden staging folder is left next
/// to it (safe to delete). If it dies during Commit(), the final folder holds the complete old or the complete new
/// set (with the two-rename fallback it may be absent, the old set then being in `.<name>.cairn-old-XXXXXX`), and
/// the other set is left in a hidden sibling folder.
///
/// Because the whole folder is replaced, an existing folder may only hold files this output writes (as judged
/// by `owns`); anything else (another file, a subfolder) is refused before anything is written, so that
/// `--out .` or `--out ~` cannot delete unrelated files. The working folder (or a folder holding it) is refused
/// too.
class AtomicOutputDirectory {
 public:
  /// Says whether a file name found in an existing final folder is one this output writes (e.g. a file of an
  /// earlier run of the same command).
  using OwnsName = std::function<bool(const std::string& name)>;

  /// Checks `path` and creates the staging folder (and the parent folders of `path` if missing). Throws
  /// std::runtime_error naming the folder and the reason when `path` exists and is not a folder, holds an entry
  /// `owns` refuses, is or holds the working folder, or when the staging folder cannot be created (the parent is
  /// not writable): so a command can construct this before its long computation and fail fast.
  AtomicOutputDirectory(const std::string& path, OwnsName owns);

  /// Removes the staging folder (and what was written into it) unless Commit() succeeded.
  ~AtomicOutputDirectory();

  AtomicOutputDirectory(const AtomicOutputDirectory&) = delete;
  AtomicOutputDirectory& operator=(const AtomicOutputDirectory&) = delete;

  /// The final folder as given.
  const std::string& path() const { return path_; }

  /// Where to write the file `name` (a plain file name, no folder) before Commit().
  std::string StagedPath(const std::string& name) const;

  /// Writes the file `name` into the staging folder. Throws std::runtime_error naming the final path on failure.
  void WriteFile(const std::string& name, const std::string& contents);

  /// Makes the staged files the folder's contents (see the class comment). Throws std::runtime_error naming the
  /// folder if the swap fails (the old set is then still in place). Call at most once.
  void Commit();

 private:
  std::string path_;      // as given, for messages
  std::string target_;    // absolute, normalised, symbolic links resolved
  std::string staging_;   // empty once committed or removed
  bool committed_{false};
};

}  // namespace cairn
