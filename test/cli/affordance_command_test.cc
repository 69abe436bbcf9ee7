// Runs `cairn affordance` as a user would: the experiments' files are written, two runs give the same bytes, and
// bad input is one line (usage errors exit 2, failures exit 1).

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "run_cairn_streams.h"
#include "test_paths.h"

namespace {

namespace fs = std::filesystem;
using cairn::test::CairnStreams;
using cairn::test::RunCairnStreams;
using ::testing::HasSubstr;
using ::testing::StartsWith;

std::string Slurp(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

class AffordanceCommandTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::path(CAIRN_BINARY_DIR) / "test-affordance" /
           ::testing::UnitTest::GetInstance()->current_test_info()->name();
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  fs::path dir_;
};

TEST_F(AffordanceCommandTest, WritesResultsAndPlotsDeterministically) {
  const std::string out = (dir_ / "run").string();
  const CairnStreams run = RunCairnStreams("affordance --episodes 4 --samples 1 --seed 3 --out " + out);
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_THAT(run.out, HasSubstr("leave-one-out k=1"));
  EXPECT_THAT(run.out, HasSubstr("change B"));
  const std::string json = Slurp(fs::path(out) / "affordance.json");
  EXPECT_THAT(json, StartsWith("{\"seed\": 3, \"episodes\": 4, \"samples_per_object\": 1"));
  for (const char* key : {"\"leave_one_out\"", "\"incremental\"", "\"alpha_sweep\"", "\"change_detection\"",
                          "\"data_set_2_to_1\"", "\"(2) novel stump\""}) {
    EXPECT_THAT(json, HasSubstr(key));
  }
  for (const char* png : {"confidence.png", "interactions.png", "confusion.png"}) {
    EXPECT_THAT(Slurp(fs::path(out) / png), StartsWith("\x89PNG")) << png;
  }
  const std::string again = (dir_ / "again").string();
  ASSERT_EQ(RunCairnStreams("affordance --episodes 4 --samples 1 --seed 3 --out " + again).exit_code, 0);
  EXPECT_EQ(Slurp(fs::path(again) / "affordance.json"), json);
  EXPECT_EQ(Slurp(fs::path(again) / "confidence.png"), Slurp(fs::path(out) / "confidence.png"));
}

TEST_F(AffordanceCommandTest, BadInputIsOneLine) {
  const CairnStreams episodes = RunCairnStreams("affordance --episodes 0");
  EXPECT_EQ(episodes.exit_code, 2);
  EXPECT_EQ(episodes.err_lines(), 1);
  EXPECT_THAT(episodes.err, HasSubstr("--episodes '0' is out of range"));
  const CairnStreams samples = RunCairnStreams("affordance --samples abc");
  EXPECT_EQ(samples.exit_code, 2);
  EXPECT_THAT(samples.err, HasSubstr("--samples 'abc' is not a number"));
  const fs::path file = dir_ / "file";
  std::ofstream(file) << "x";
  const CairnStreams out = RunCairnStreams("affordance --episodes 1 --samples 1 --out " + file.string());
  EXPECT_EQ(out.exit_code, 1);
  EXPECT_EQ(out.err_lines(), 1);
  EXPECT_THAT(out.err, HasSubstr(file.string()));
}

}  // namespace
