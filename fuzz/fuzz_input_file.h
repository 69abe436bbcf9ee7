#pragma once

/// @file
/// The scratch file through which the fuzz harnesses feed parsers that take a path.

#include <string>
#include <string_view>

namespace cairn::fuzz {

/// One file in a private folder that a harness rewrites for every input and hands to a parser by path.
///
/// The folder is in /dev/shm when that exists (a fuzzer writes the file a million times; memory is faster than a
/// disk and wears nothing out), else in the system's temporary folder. Its name carries the process id, so
/// fuzzers and tests running at the same time never share one. The folder and all in it are removed when the
/// object is destroyed (a harness keeps one for the process's lifetime). Not thread-safe: libFuzzer and the
/// regression test call a harness from one thread.
class FuzzInputFile {
 public:
  /// Creates the folder; the file is called `name` in it (the extension matters to readers that look at it, such
  /// as cv::imread). Throws std::runtime_error naming the folder if it cannot be created.
  explicit FuzzInputFile(const std::string& name);
  ~FuzzInputFile();
  FuzzInputFile(const FuzzInputFile&) = delete;
  FuzzInputFile& operator=(const FuzzInputFile&) = delete;

  /// Makes `link_name` in the folder a symbolic link to `target`, for the files an input names relative to its
  /// own folder (a walking model's URDF, an ONNX description's network). Throws std::runtime_error on failure.
  void Link(const std::string& link_name, const std::string& target) const;

  /// Replaces the file's contents with `bytes` and returns its path. Throws std::runtime_error if it cannot.
  const std::string& Write(std::string_view bytes) const;

  /// The folder holding the file.
  const std::string& folder() const { return folder_; }

 private:
  std::string folder_;
  std::string path_;
};

}  // namespace cairn::fuzz
