#include "cairn/common/atomic_file.h"

#include <sys/stat.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

namespace cairn {
namespace {

namespace fs = std::filesystem;

std::string ReadAll(const fs::path& path) {
  std::ifstream in(path);
  std::stringstream buffer;
  buffer << in.rdbuf();
  return buffer.str();
}

TEST(AtomicFileTest, ReplacesContentsAndLeavesNoTemporaryFiles) {
  const fs::path dir = fs::temp_directory_path() / ("cairn_atomic_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const fs::path file = dir / "out.csv";
  WriteFileAtomically(file.string(), "first\n");
  WriteFileAtomically(file.string(), "second\n");
  EXPECT_EQ(ReadAll(file), "second\n");
  int entries = 0;
  for ([[maybe_unused]] const auto& entry : fs::directory_iterator(dir)) ++entries;
  EXPECT_EQ(entries, 1);
  struct stat info {};
  ASSERT_EQ(::stat(file.c_str(), &info), 0);
  EXPECT_NE(info.st_mode & S_IRGRP, 0u) << "the file keeps the usual permissions, not mkstemp's 0600";
  fs::remove_all(dir);
}

TEST(AtomicFileTest, MissingFolderIsAClearError) {
  try {
    WriteFileAtomically("/nonexistent_cairn_dir/out.csv", "x");
    FAIL() << "expected an exception";
  } catch (const std::runtime_error& e) {
    EXPECT_THAT(e.what(), testing::HasSubstr("Cannot write '/nonexistent_cairn_dir/out.csv'"));
    EXPECT_THAT(e.what(), testing::HasSubstr("No such file or directory"));
  }
}

}  // namespace
}  // namespace cairn
