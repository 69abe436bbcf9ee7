#include "cairn/common/atomic_output_directory.h"

#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "expect_throws.h"

namespace cairn {
namespace {

namespace fs = std::filesystem;

std::string ReadAll(const fs::path& path) {
  std::ifstream in(path);
  std::stringstream buffer;
  buffer << in.rdbuf();
  return buffer.str();
}

std::set<std::string> Names(const fs::path& folder) {
  std::set<std::string> names;
  for (const auto& entry : fs::directory_iterator(folder)) names.insert(entry.path().filename().string());
  return names;
}

bool Numbered(const std::string& name) { return name.size() == 5 && name.compare(1, 4, ".txt") == 0; }

class AtomicOutputDirectoryTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("cairn_atomic_dir_" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  void WriteSet(const fs::path& out, int count, const std::string& tag) {
    AtomicOutputDirectory set(out.string(), Numbered);
    for (int i = 0; i < count; ++i) set.WriteFile(std::to_string(i) + ".txt", tag);
    set.Commit();
  }
  fs::path dir_;
};

TEST_F(AtomicOutputDirectoryTest, CreatesTheFolderAndItsParents) {
  const fs::path out = dir_ / "a" / "b" / "out";
  WriteSet(out, 2, "new");
  EXPECT_EQ(Names(out), (std::set<std::string>{"0.txt", "1.txt"}));
  EXPECT_EQ(ReadAll(out / "1.txt"), "new");
  EXPECT_EQ(Names(dir_ / "a" / "b"), std::set<std::string>{"out"}) << "no staging folder is left";
  struct stat info {};
  ASSERT_EQ(::stat(out.c_str(), &info), 0);
  EXPECT_NE(info.st_mode & S_IRGRP, 0u) << "the folder has the usual permissions, not mkdtemp's 0700";
}

TEST_F(AtomicOutputDirectoryTest, ReplacesALargerEarlierSetWhole) {
  const fs::path out = dir_ / "out";
  WriteSet(out, 3, "old");
  WriteSet(out, 1, "new");
  EXPECT_EQ(Names(out), std::set<std::string>{"0.txt"});
  EXPECT_EQ(ReadAll(out / "0.txt"), "new");
  EXPECT_EQ(Names(dir_), std::set<std::string>{"out"});
}

TEST_F(AtomicOutputDirectoryTest, WithoutCommitTheOldSetStaysAndNothingIsLeft) {
  const fs::path out = dir_ / "out";
  WriteSet(out, 2, "old");
  {
    AtomicOutputDirectory set(out.string(), Numbered);
    set.WriteFile("0.txt", "half of a new set");
    EXPECT_TRUE(fs::exists(set.StagedPath("0.txt")));
    EXPECT_EQ(ReadAll(out / "0.txt"), "old") << "nothing is visible before Commit()";
  }  // e.g. the command failed mid-way
  EXPECT_EQ(Names(out), (std::set<std::string>{"0.txt", "1.txt"}));
  EXPECT_EQ(ReadAll(out / "0.txt"), "old");
  EXPECT_EQ(Names(dir_), std::set<std::string>{"out"});
}

TEST_F(AtomicOutputDirectoryTest, RefusesFoldersItWouldWronglyDelete) {
  const fs::path out = dir_ / "out";
  fs::create_directories(out / "sub");
  CAIRN_EXPECT_THROWS_WITH(AtomicOutputDirectory(out.string(), Numbered), std::runtime_error,
                           "it holds 'sub', which this command does not write");
  fs::remove(out / "sub");
  std::ofstream(out / "notes.md") << "mine";
  CAIRN_EXPECT_THROWS_WITH(AtomicOutputDirectory(out.string(), Numbered), std::runtime_error,
                           "Cannot write the folder '" + out.string() + "': it holds 'notes.md'");
  EXPECT_EQ(ReadAll(out / "notes.md"), "mine");
  // A temporary file of an interrupted earlier write belongs to the set.
  fs::remove(out / "notes.md");
  std::ofstream(out / "0.txt.tmp.AbC123") << "partial";
  WriteSet(out, 1, "new");
  EXPECT_EQ(Names(out), std::set<std::string>{"0.txt"});

  const fs::path cwd = fs::current_path();
  fs::current_path(out);
  CAIRN_EXPECT_THROWS_WITH(AtomicOutputDirectory(".", Numbered), std::runtime_error, "the working folder");
  CAIRN_EXPECT_THROWS_WITH(AtomicOutputDirectory(dir_.string(), Numbered), std::runtime_error, "the working folder");
  fs::current_path(cwd);
  CAIRN_EXPECT_THROWS_WITH(AtomicOutputDirectory("/", Numbered), std::runtime_error, "it is a root folder");
  std::ofstream(dir_ / "file") << "x";
  CAIRN_EXPECT_THROWS_WITH(AtomicOutputDirectory((dir_ / "file").string(), Numbered), std::runtime_error,
                           "it exists and is not a folder");
  CAIRN_EXPECT_THROWS_WITH(AtomicOutputDirectory((dir_ / "file" / "out").string(), Numbered), std::runtime_error,
                           "its parent folder '" + (dir_ / "file").string() + "' cannot be created");
}

TEST_F(AtomicOutputDirectoryTest, ASymbolicLinkKeepsPointingAtTheReplacedFolder) {
  const fs::path real = dir_ / "real";
  WriteSet(real, 2, "old");
  fs::create_directory_symlink(real, dir_ / "link");
  WriteSet(dir_ / "link", 1, "new");
  EXPECT_TRUE(fs::is_symlink(dir_ / "link"));
  EXPECT_EQ(Names(real), std::set<std::string>{"0.txt"});
  EXPECT_EQ(ReadAll(dir_ / "link" / "0.txt"), "new");
}

TEST_F(AtomicOutputDirectoryTest, WriteErrorsNameTheFinalPath) {
  const fs::path out = dir_ / "out";
  AtomicOutputDirectory set(out.string(), Numbered);
  fs::create_directories(set.StagedPath("0.txt"));  // a folder where the file should go
  CAIRN_EXPECT_THROWS_WITH(set.WriteFile("0.txt", "x"), std::runtime_error,
                           "Cannot write '" + out.string() + "/0.txt': it is a folder");
}

}  // namespace
}  // namespace cairn
