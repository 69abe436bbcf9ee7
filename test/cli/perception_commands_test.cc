// Runs `cairn stereo-eval` and `cairn occupancy` as a user would and checks exit codes and key output.

#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

namespace {

using ::testing::HasSubstr;
using ::testing::Not;

struct CliRun {
  int exit_code;
  std::string output;  // stdout and stderr together
};

CliRun Cairn(const std::string& arguments) {
  const std::string command = std::string(CAIRN_CLI_PATH) + " " + arguments + " 2>&1";
  FILE* pipe = ::popen(command.c_str(), "r");
  EXPECT_NE(pipe, nullptr);
  CliRun run{-1, ""};
  std::array<char, 4096> buffer{};
  while (std::fgets(buffer.data(), buffer.size(), pipe) != nullptr) run.output += buffer.data();
  const int status = ::pclose(pipe);
  run.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return run;
}

std::string Venus(const std::string& file) { return std::string(CAIRN_SHARED_DIR) + "/data/middlebury/venus/" + file; }

std::string VenusPair() {
  return "stereo-eval --left " + Venus("im2.png") + " --right " + Venus("im6.png") + " --gt " + Venus("disp2.png") +
         " --gt-scale 8";
}

TEST(PerceptionCommandsTest, StereoEvalPrintsTheMeasuresAsTextAndJson) {
  const CliRun text = Cairn(VenusPair() + " --gt-right " + Venus("disp6.png") +
                         " --dmax 31 --cost btsad --window 9 --model merrell --params ml");
  ASSERT_EQ(text.exit_code, 0) << text.output;
  for (const char* key : {"bad-pixel rate", "AUC", "optimal", "C(d in GT)_badpx", "merrell(", "cost volume"}) {
    EXPECT_THAT(text.output, HasSubstr(key));
  }
  const CliRun json = Cairn(VenusPair() + " --dmax 31 --cost ssd --window 5 --model exp --params 300 --json");
  ASSERT_EQ(json.exit_code, 0) << json.output;
  for (const char* key : {"\"bad_pixel_rate\": 0.", "\"auc\": ", "\"auc_optimal\": ", "\"c_gt_badpx\": ",
                          "\"parameter\": 300", "\"ms_cost_volume\": ", "\"ms_confidence\": "}) {
    EXPECT_THAT(json.output, HasSubstr(key));
  }
  EXPECT_EQ(json.output.front(), '{');
}

TEST(PerceptionCommandsTest, StereoEvalBadInputExitsWithOneAndSaysWhy) {
  const CliRun missing = Cairn("stereo-eval --left " + Venus("im2.png") + " --right /no/such.png --gt " +
                            Venus("disp2.png") + " --gt-scale 8");
  EXPECT_EQ(missing.exit_code, 1);
  EXPECT_THAT(missing.output, HasSubstr("cannot open image '/no/such.png'"));
  const CliRun even = Cairn(VenusPair() + " --window 8");
  EXPECT_EQ(even.exit_code, 1);
  EXPECT_THAT(even.output, HasSubstr("window 8 must be odd"));
  const CliRun model = Cairn(VenusPair() + " --model merel");
  EXPECT_EQ(model.exit_code, 1);
  EXPECT_THAT(model.output, HasSubstr("did you mean 'merrell'?"));
  const CliRun size = Cairn("stereo-eval --left " + Venus("im2.png") + " --right " + std::string(CAIRN_SHARED_DIR) +
                         "/data/middlebury/tsukuba/im6.png --gt " + Venus("disp2.png") + " --gt-scale 8");
  EXPECT_EQ(size.exit_code, 1);
  EXPECT_THAT(size.output, HasSubstr("pass a rectified pair of equal size"));
  const CliRun wide = Cairn(VenusPair() + " --dmax 1000");
  EXPECT_EQ(wide.exit_code, 1);
  EXPECT_THAT(wide.output, HasSubstr("wider than the image"));
  const CliRun usage = Cairn("stereo-eval --left " + Venus("im2.png"));
  EXPECT_EQ(usage.exit_code, 2);
  EXPECT_THAT(usage.output, HasSubstr("--right is required"));
}

TEST(PerceptionCommandsTest, OccupancyPrintsPrecisionAndRecallPerFrame) {
  const CliRun text = Cairn("occupancy --scenario bars --model merrell --frames 2");
  ASSERT_EQ(text.exit_code, 0) << text.output;
  EXPECT_THAT(text.output, HasSubstr("frame  0  precision"));
  EXPECT_THAT(text.output, HasSubstr("frame  1  precision"));
  EXPECT_THAT(text.output, Not(HasSubstr("frame  2")));
  EXPECT_THAT(text.output, HasSubstr("final     precision"));
  EXPECT_THAT(text.output, HasSubstr("ms per frame"));
  const CliRun json = Cairn("occupancy --scenario bars --model wta --noise-var 13 --frames 1 --json");
  ASSERT_EQ(json.exit_code, 0) << json.output;
  for (const char* key : {"\"model\": \"wta\"", "\"noise_var\": 13", "\"frame\": 0", "\"precision\": ",
                          "\"recall\": ", "\"ms_per_frame\": "}) {
    EXPECT_THAT(json.output, HasSubstr(key));
  }
}

TEST(PerceptionCommandsTest, OccupancyBadInputExitsWithOneOrTwo) {
  const CliRun model = Cairn("occupancy --model gaussian --frames 1");
  EXPECT_EQ(model.exit_code, 1);
  EXPECT_THAT(model.output, HasSubstr("unknown occupancy model 'gaussian'"));
  const CliRun scenario = Cairn("occupancy --scenario /no/such.yaml --frames 1");
  EXPECT_EQ(scenario.exit_code, 1);
  EXPECT_THAT(scenario.output, HasSubstr("/no/such.yaml"));
  const CliRun frames = Cairn("occupancy --frames 0");
  EXPECT_EQ(frames.exit_code, 1);
  EXPECT_THAT(frames.output, HasSubstr("0 frames"));
  const CliRun flag = Cairn("occupancy --bogus");
  EXPECT_EQ(flag.exit_code, 2);
  EXPECT_THAT(flag.output, HasSubstr("--bogus"));
}

}  // namespace
