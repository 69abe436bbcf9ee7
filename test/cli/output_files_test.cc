// Failures (exit 1, one line naming the file) and output files, as a user meets them: outputs are replaced
// atomically (the old file or folder stays whole when a write fails), multi-file outputs leave the old set or the
// new set, standard output to a full device is an error, and decoders' own text never reaches the user.

#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "run_cairn_streams.h"
#include "test_paths.h"

namespace {

using cairn::test::CairnStreams;
using cairn::test::RunCairnStreams;
using ::testing::HasSubstr;
using ::testing::Not;
namespace fs = std::filesystem;

std::string Read(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

std::set<std::string> Names(const fs::path& folder) {
  std::set<std::string> names;
  for (const auto& entry : fs::directory_iterator(folder)) names.insert(entry.path().filename().string());
  return names;
}

// Checks a failure: exit 1 and one line "cairn <subcommand>: error: ..." containing `expected`.
void ExpectFailure(const CairnStreams& run, const std::string& expected) {
  EXPECT_EQ(run.exit_code, 1) << run.err;
  EXPECT_EQ(run.err_lines(), 1) << run.err;
  EXPECT_THAT(run.err, HasSubstr(": error: "));
  EXPECT_THAT(run.err, HasSubstr(expected));
}

class OutputFilesTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("cairn_output_files_" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  // A small labelled render to feed `cairn friction`.
  std::string Image() {
    const fs::path data = dir_ / "render";
    if (!fs::exists(data / "image_0000.png")) {
      const CairnStreams run =
          RunCairnStreams("friction-dataset --out " + data.string() + " --images 1 --width 48 --height 32");
      EXPECT_EQ(run.exit_code, 0) << run.err;
    }
    return (data / "image_0000.png").string();
  }
  fs::path dir_;
};

TEST_F(OutputFilesTest, StandardOutputToAFullDeviceIsAFailure) {
  for (const std::string& arguments : {std::string("diagram"), std::string("pendulum --duration 0.01 --json"),
                                       std::string("--help")}) {
    const CairnStreams run = RunCairnStreams(arguments, "/dev/full");
    ExpectFailure(run, "cannot write to standard output (No space left on device); the output is lost");
  }
}

TEST_F(OutputFilesTest, PlyReplacesTheOldFileOnlyWhenTheNewOneIsComplete) {
  const fs::path ply = dir_ / "grid.ply";
  std::ofstream(ply) << "an earlier good file\n";
  // The new PLY is larger than the 1 KiB the file size limit allows: the write fails part-way (it used to leave a
  // truncated PLY in place of the old one).
  const CairnStreams failed =
      RunCairnStreams("occupancy --frames 1 --ply " + ply.string(), "/dev/null", "ulimit -f 1; trap '' XFSZ;");
  ExpectFailure(failed, "Cannot write '" + ply.string() + "': writing failed (File too large).");
  EXPECT_EQ(Read(ply), "an earlier good file\n");
  EXPECT_EQ(Names(dir_), std::set<std::string>{"grid.ply"}) << "no temporary file is left";
  const CairnStreams written = RunCairnStreams("occupancy --frames 1 --ply " + ply.string());
  ASSERT_EQ(written.exit_code, 0) << written.err;
  EXPECT_THAT(Read(ply), ::testing::StartsWith("ply\nformat ascii 1.0\nelement vertex "));
}

TEST_F(OutputFilesTest, FrictionDatasetReplacesALargerEarlierDatasetWhole) {
  const fs::path out = dir_ / "data";
  ASSERT_EQ(RunCairnStreams("friction-dataset --out " + out.string() + " --images 3 --width 32 --height 32").exit_code,
            0);
  EXPECT_EQ(Names(out).size(), 7u);
  const CairnStreams smaller =
      RunCairnStreams("friction-dataset --out " + out.string() + " --images 1 --width 32 --height 32 --seed 5");
  ASSERT_EQ(smaller.exit_code, 0) << smaller.err;
  // The pairs 0001 and 0002 of the earlier dataset used to stay next to the new pair 0000.
  EXPECT_EQ(Names(out), (std::set<std::string>{"image_0000.png", "label_0000.png", "labels.txt"}));
  EXPECT_EQ(Names(dir_), std::set<std::string>{"data"}) << "no staging folder is left";
}

TEST_F(OutputFilesTest, AFolderHoldingOtherFilesIsNotReplaced) {
  const fs::path out = dir_ / "mine";
  fs::create_directories(out);
  std::ofstream(out / "notes.txt") << "keep me\n";
  ExpectFailure(RunCairnStreams("friction-dataset --out " + out.string() + " --images 1 --width 32 --height 32"),
                "it holds 'notes.txt', which this command does not write");
  EXPECT_EQ(Read(out / "notes.txt"), "keep me\n");
  const std::string here = "cd " + out.string() + " &&";
  ExpectFailure(RunCairnStreams("friction-dataset --out . --images 1", "", "rm " + (out / "notes.txt").string() +
                                ";" + here),
                "it is (or holds) the working folder");
}

TEST_F(OutputFilesTest, FrictionLeavesTheOldSetWhenItFailsAfterStarting) {
  const std::string image = Image();
  const fs::path out = dir_ / "friction";
  ASSERT_EQ(RunCairnStreams("friction --image " + image + " --out " + out.string()).exit_code, 0);
  const std::string json = Read(out / "friction.json");
  ASSERT_THAT(json, HasSubstr("\"eta\": 0.95"));
  // The segmenter is made after the output folder is prepared: the failure comes mid-way.
  ExpectFailure(RunCairnStreams("friction --image " + image + " --segmenter magic --eta 0.5 --out " + out.string()),
                "Unknown segmenter 'magic'");
  EXPECT_EQ(Read(out / "friction.json"), json);
  EXPECT_EQ(Names(out), (std::set<std::string>{"friction.json", "friction.png", "materials.png"}));
  EXPECT_EQ(Names(dir_), (std::set<std::string>{"friction", "render"})) << "no staging folder is left";
  ASSERT_EQ(RunCairnStreams("friction --image " + image + " --eta 0.5 --out " + out.string()).exit_code, 0);
  EXPECT_THAT(Read(out / "friction.json"), HasSubstr("\"eta\": 0.5"));
}

TEST_F(OutputFilesTest, AFolderWhereAFileIsExpectedIsNamed) {
  const std::string folder = dir_.string();
  ExpectFailure(RunCairnStreams("friction --image " + folder + " --out " + folder + "/o"),
                "--image '" + folder + "' is a folder; give an image file");
  ExpectFailure(RunCairnStreams("stereo-eval --left " + folder + " --right " + folder + " --gt " + folder +
                                " --gt-scale 8"),
                "--left '" + folder + "' is a folder; give an image file");
  ExpectFailure(RunCairnStreams("model-info " + folder), "the URDF '" + folder + "' is a folder; give a URDF file");
  ExpectFailure(RunCairnStreams("plan --scenario " + folder), "--scenario '" + folder + "' is a folder");
  ExpectFailure(RunCairnStreams("occupancy --scenario " + folder), "--scenario '" + folder + "' is a folder");
  ExpectFailure(RunCairnStreams("friction --image " + Image() + " --registry " + folder + " --out " + folder + "/o"),
                "--registry '" + folder + "' is a folder");
  // Outputs: refused before any work.
  ExpectFailure(RunCairnStreams("pendulum --duration 0.01 --csv " + folder),
                "--csv '" + folder + "' is a folder; give a file name");
  ExpectFailure(RunCairnStreams("occupancy --frames 1 --ply " + folder), "--ply '" + folder + "' is a folder");
  ExpectFailure(RunCairnStreams("friction-train --out " + folder), "--out '" + folder + "' is a folder");
  ExpectFailure(RunCairnStreams("pendulum --duration 0.01 --csv " + folder + "/no/such/log.csv"),
                "its folder '" + folder + "/no/such' does not exist");
}

TEST_F(OutputFilesTest, DecoderTextNeverReachesTheUser) {
  const fs::path corrupt = dir_ / "corrupt.png";
  const std::string good = Read(Image());
  std::ofstream(corrupt, std::ios::binary) << good.substr(0, good.size() / 2);  // a truncated PNG
  for (const std::string& arguments :
       {"friction --image " + corrupt.string() + " --out " + (dir_ / "o").string(),
        "stereo-eval --left " + corrupt.string() + " --right " + corrupt.string() + " --gt " + corrupt.string() +
            " --gt-scale 8",
        "friction --image " + (dir_ / "missing.png").string() + " --out " + (dir_ / "o").string()}) {
    const CairnStreams run = RunCairnStreams(arguments);
    EXPECT_EQ(run.exit_code, 1) << arguments;
    EXPECT_EQ(run.err_lines(), 1) << run.err;
    EXPECT_THAT(run.err, Not(HasSubstr("libpng"))) << run.err;
    EXPECT_THAT(run.err, Not(HasSubstr("WARN"))) << run.err;
    EXPECT_THAT(run.err, Not(HasSubstr("OpenCV"))) << run.err;
  }
}

TEST_F(OutputFilesTest, LibraryRefusalsAreFailuresWithTheLibraryMessage) {
  // In the option's range (odd, at most 2051) but beyond what SSD sums allow: the stereo library says so.
  const std::string venus = std::string(CAIRN_SHARED_DIR) + "/data/middlebury/venus/";
  const CairnStreams run = RunCairnStreams("stereo-eval --left " + venus + "im2.png --right " + venus +
                                           "im6.png --gt " + venus + "disp2.png --gt-scale 8 --cost ssd --window 183");
  ExpectFailure(run, "stereo window 183 is larger than 181");
}

}  // namespace
