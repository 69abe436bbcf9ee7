// Runs `cairn stereo-eval` and `cairn occupancy` as a user would and checks exit codes and key output.

#include <array>
#include <cstdio>
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "run_cairn.h"

namespace {

using cairn::test::CairnRun;
using cairn::test::RunCairn;

using ::testing::HasSubstr;
using ::testing::Not;

std::string Venus(const std::string& file) { return std::string(CAIRN_SHARED_DIR) + "/data/middlebury/venus/" + file; }

std::string VenusPair() {
  return "stereo-eval --left " + Venus("im2.png") + " --right " + Venus("im6.png") + " --gt " + Venus("disp2.png") +
         " --gt-scale 8";
}

TEST(PerceptionCommandsTest, StereoEvalPrintsTheMeasuresAsTextAndJson) {
  const CairnRun text = RunCairn(VenusPair() + " --gt-right " + Venus("disp6.png") +
                         " --dmax 31 --cost btsad --window 9 --model merrell --params ml");
  ASSERT_EQ(text.exit_code, 0) << text.output;
  for (const char* key : {"bad-pixel rate", "AUC", "optimal", "C(d in GT)_badpx", "merrell(", "cost volume"}) {
    EXPECT_THAT(text.output, HasSubstr(key));
  }
  const CairnRun json = RunCairn(VenusPair() + " --dmax 31 --cost ssd --window 5 --model exp --params 300 --json");
  ASSERT_EQ(json.exit_code, 0) << json.output;
  for (const char* key : {"\"bad_pixel_rate\": 0.", "\"auc\": ", "\"auc_optimal\": ", "\"c_gt_badpx\": ",
                          "\"parameter\": 300", "\"ms_cost_volume\": ", "\"ms_confidence\": "}) {
    EXPECT_THAT(json.output, HasSubstr(key));
  }
  EXPECT_EQ(json.output.front(), '{');
}

TEST(PerceptionCommandsTest, StereoEvalBadInputExitsWithOneAndSaysWhy) {
  const CairnRun missing = RunCairn("stereo-eval --left " + Venus("im2.png") + " --right /no/such.png --gt " +
                            Venus("disp2.png") + " --gt-scale 8");
  EXPECT_EQ(missing.exit_code, 1);
  EXPECT_THAT(missing.output, HasSubstr("cannot open image '/no/such.png'"));
  const CairnRun even = RunCairn(VenusPair() + " --window 8");
  EXPECT_EQ(even.exit_code, 1);
  EXPECT_THAT(even.output, HasSubstr("window 8 must be odd"));
  const CairnRun model = RunCairn(VenusPair() + " --model merel");
  EXPECT_EQ(model.exit_code, 1);
  EXPECT_THAT(model.output, HasSubstr("did you mean 'merrell'?"));
  const CairnRun size = RunCairn("stereo-eval --left " + Venus("im2.png") + " --right " + std::string(CAIRN_SHARED_DIR) +
                         "/data/middlebury/tsukuba/im6.png --gt " + Venus("disp2.png") + " --gt-scale 8");
  EXPECT_EQ(size.exit_code, 1);
  EXPECT_THAT(size.output, HasSubstr("pass a rectified pair of equal size"));
  const CairnRun wide = RunCairn(VenusPair() + " --dmax 1000");
  EXPECT_EQ(wide.exit_code, 1);
  EXPECT_THAT(wide.output, HasSubstr("wider than the image"));
  const CairnRun usage = RunCairn("stereo-eval --left " + Venus("im2.png"));
  EXPECT_EQ(usage.exit_code, 2);
  EXPECT_THAT(usage.output, HasSubstr("--right is required"));
}

TEST(PerceptionCommandsTest, OccupancyPrintsPrecisionAndRecallPerFrame) {
  const CairnRun text = RunCairn("occupancy --scenario bars --model merrell --frames 2");
  ASSERT_EQ(text.exit_code, 0) << text.output;
  EXPECT_THAT(text.output, HasSubstr("frame  0  precision"));
  EXPECT_THAT(text.output, HasSubstr("frame  1  precision"));
  EXPECT_THAT(text.output, Not(HasSubstr("frame  2")));
  EXPECT_THAT(text.output, HasSubstr("final     precision"));
  EXPECT_THAT(text.output, HasSubstr("ms per frame"));
  const CairnRun json = RunCairn("occupancy --scenario bars --model wta --noise-var 13 --frames 1 --json");
  ASSERT_EQ(json.exit_code, 0) << json.output;
  for (const char* key : {"\"model\": \"wta\"", "\"noise_var\": 13", "\"frame\": 0", "\"precision\": ",
                          "\"recall\": ", "\"ms_per_frame\": "}) {
    EXPECT_THAT(json.output, HasSubstr(key));
  }
}

TEST(PerceptionCommandsTest, OccupancyBadInputExitsWithOneOrTwo) {
  const CairnRun model = RunCairn("occupancy --model gaussian --frames 1");
  EXPECT_EQ(model.exit_code, 1);
  EXPECT_THAT(model.output, HasSubstr("unknown occupancy model 'gaussian'"));
  const CairnRun scenario = RunCairn("occupancy --scenario /no/such.yaml --frames 1");
  EXPECT_EQ(scenario.exit_code, 1);
  EXPECT_THAT(scenario.output, HasSubstr("/no/such.yaml"));
  const CairnRun frames = RunCairn("occupancy --frames 0");
  EXPECT_EQ(frames.exit_code, 1);
  EXPECT_THAT(frames.output, HasSubstr("0 frames"));
  const CairnRun flag = RunCairn("occupancy --bogus");
  EXPECT_EQ(flag.exit_code, 2);
  EXPECT_THAT(flag.output, HasSubstr("--bogus"));
}

}  // namespace
