// Runs `cairn stereo-eval` and `cairn occupancy` as a user would and checks exit codes and key output.

#include <algorithm>
#include <array>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>

#include "run_cairn.h"
#include "test_paths.h"

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

TEST(PerceptionCommandsTest, StereoEvalJsonKeepsSmallParameters) {
  // "%f" printed 1e-300 as 0.000000.
  const CairnRun json = RunCairn(VenusPair() + " --dmax 31 --model exp --params 1e-300 --json");
  ASSERT_EQ(json.exit_code, 0) << json.output;
  EXPECT_THAT(json.output, HasSubstr("\"parameter\": 1e-300,"));
}

TEST(PerceptionCommandsTest, StereoEvalBadInputExitsWithOneAndSaysWhy) {
  const CairnRun missing = RunCairn("stereo-eval --left " + Venus("im2.png") + " --right /no/such.png --gt " +
                            Venus("disp2.png") + " --gt-scale 8");
  EXPECT_EQ(missing.exit_code, 1);
  EXPECT_THAT(missing.output, HasSubstr("--right '/no/such.png' does not exist"));
  const CairnRun even = RunCairn(VenusPair() + " --window 8");
  EXPECT_EQ(even.exit_code, 2);
  EXPECT_THAT(even.output, HasSubstr("--window '8' is even"));
  const CairnRun model = RunCairn(VenusPair() + " --model merel");
  EXPECT_EQ(model.exit_code, 2);
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

TEST(PerceptionCommandsTest, StereoEvalReadsSixteenBitGroundTruthAndDefaultsOnlyAbsentOptions) {
  // Venus' ground truth in the KITTI layout: 16 bits, 256 per pixel of disparity (the file's 8 per pixel x 32).
  const cv::Mat eight = cv::imread(Venus("disp2.png"), cv::IMREAD_GRAYSCALE);
  ASSERT_FALSE(eight.empty());
  cv::Mat sixteen;
  eight.convertTo(sixteen, CV_16U, 32.0);
  const std::string kitti = ::testing::TempDir() + "/perception_commands_disp2_16bit.png";
  ASSERT_TRUE(cv::imwrite(kitti, sixteen));
  const std::string pair = "stereo-eval --left " + Venus("im2.png") + " --right " + Venus("im6.png") + " --gt ";
  // Neither --gt-scale nor --dmax: the file's own scale, and the range from its largest disparity (19.75 px).
  const CairnRun automatic = RunCairn(pair + kitti + " --json");
  ASSERT_EQ(automatic.exit_code, 0) << automatic.output;
  EXPECT_THAT(automatic.output, HasSubstr("\"max_disparity\": 31,"));
  EXPECT_THAT(automatic.output, HasSubstr("\"bad_pixel_rate\": 0.0"));
  // An 8-bit file has no standard scale: the command asks for it.
  const CairnRun eight_bit = RunCairn(pair + Venus("disp2.png"));
  EXPECT_EQ(eight_bit.exit_code, 2) << eight_bit.output;
  EXPECT_THAT(eight_bit.output, HasSubstr("--gt-scale is needed: the ground truth '" + Venus("disp2.png") +
                                          "' is 8-bit"));
  // A --dmax given is used, whatever its value: 0 is no request for the automatic range (and covers no pixel).
  const CairnRun zero = RunCairn(pair + kitti + " --dmax 0");
  EXPECT_EQ(zero.exit_code, 1) << zero.output;
  EXPECT_THAT(zero.output, HasSubstr("no pixel could be evaluated"));
  const CairnRun negative = RunCairn(pair + kitti + " --dmax -1");
  EXPECT_EQ(negative.exit_code, 2) << negative.output;
  EXPECT_THAT(negative.output, HasSubstr("--dmax '-1' is out of range; give an integer from 0 to 4095"));
  std::remove(kitti.c_str());
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
  for (const char* key : {"\"scenario\": \"bars\"", "\"model\": \"wta\"", "\"noise_var\": 13", "\"frame\": 0", "\"precision\": ",
                          "\"recall\": ", "\"ms_per_frame\": "}) {
    EXPECT_THAT(json.output, HasSubstr(key));
  }
}

TEST(PerceptionCommandsTest, OccupancyBadInputExitsWithOneOrTwo) {
  const CairnRun model = RunCairn("occupancy --model gaussian --frames 1");
  EXPECT_EQ(model.exit_code, 2);
  EXPECT_THAT(model.output, HasSubstr("--model 'gaussian' is not one of"));
  const CairnRun scenario = RunCairn("occupancy --scenario /no/such.yaml --frames 1");
  EXPECT_EQ(scenario.exit_code, 1);
  EXPECT_THAT(scenario.output, HasSubstr("--scenario '/no/such.yaml' does not exist"));
  const CairnRun frames = RunCairn("occupancy --frames 0");
  EXPECT_EQ(frames.exit_code, 2);
  EXPECT_THAT(frames.output, HasSubstr("--frames '0' is out of range; give an integer from 1 to 10000"));
  // The scenarios' own limit (OccupancyScenario::kMaxFrames), one for the option and the files.
  const CairnRun many = RunCairn("occupancy --frames 10001");
  EXPECT_EQ(many.exit_code, 2);
  EXPECT_THAT(many.output, HasSubstr("--frames '10001' is out of range; give an integer from 1 to 10000"));
  const CairnRun flag = RunCairn("occupancy --bogus");
  EXPECT_EQ(flag.exit_code, 2);
  EXPECT_THAT(flag.output, HasSubstr("--bogus"));
}

std::string BoxesOnFloor() { return std::string(CAIRN_SOURCE_DIR) + "/examples/scenarios/occupancy/boxes_on_floor.yaml"; }

TEST(PerceptionCommandsTest, OccupancyRunsAYamlScenario) {
  const CairnRun run = RunCairn("occupancy --scenario " + BoxesOnFloor() + " --model merrell --frames 2 --json");
  ASSERT_EQ(run.exit_code, 0) << run.output;
  EXPECT_THAT(run.output, HasSubstr("boxes_on_floor.yaml"));
  EXPECT_THAT(run.output, HasSubstr("\"noise_var\": 13"));  // the file's noise
  EXPECT_THAT(run.output, HasSubstr("\"frame\": 1"));
  EXPECT_THAT(run.output, Not(HasSubstr("\"frame\": 2")));
  // The boxes are seen: some occupied cells are right after two frames.
  const auto at = run.output.rfind("\"precision\": ");
  ASSERT_NE(at, std::string::npos);
  EXPECT_GT(std::stod(run.output.substr(at + 13)), 0.3) << run.output;
  const CairnRun noise = RunCairn("occupancy --scenario " + BoxesOnFloor() + " --model wta --frames 1 --noise-var 0 --json");
  ASSERT_EQ(noise.exit_code, 0) << noise.output;
  EXPECT_THAT(noise.output, HasSubstr("\"noise_var\": 0,"));
  const CairnRun too_many = RunCairn("occupancy --scenario " + BoxesOnFloor() + " --frames 11");
  EXPECT_EQ(too_many.exit_code, 1);
  EXPECT_THAT(too_many.output, HasSubstr("has 10 frames"));
}

TEST(PerceptionCommandsTest, OccupancyRefusesAScenarioFileLargerThanTwoMebibytesBeforeParsingIt) {
  const std::string path = ::testing::TempDir() + "/perception_commands_padded.yaml";
  std::ofstream(path) << "# " << std::string(2u << 20, 'x') << "\n";
  const CairnRun run = RunCairn("occupancy --scenario " + path);
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_THAT(run.output, HasSubstr("Cannot read '" + path + "': it has 2097155 bytes, more than the 2097152 a file "
                                    "of its kind may have."));
  std::remove(path.c_str());
}

TEST(PerceptionCommandsTest, OccupancyReportsTheKeyAndLineOfAMalformedScenario) {
  std::ifstream in(BoxesOnFloor());
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::string from = "half_extents: [0.25, 0.25, 0.25]";
  const auto at = text.find(from);
  ASSERT_NE(at, std::string::npos);
  const int line = 1 + static_cast<int>(std::count(text.begin(), text.begin() + static_cast<long>(at), '\n'));
  text.replace(at, from.size(), "half_extents: [0.25, 0.25]");
  const std::string path = ::testing::TempDir() + "/perception_commands_bad_scenario.yaml";
  std::ofstream(path) << text;
  const CairnRun run = RunCairn("occupancy --scenario " + path);
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_THAT(run.output, HasSubstr("line " + std::to_string(line) + ": 'objects[2].half_extents' must be a list of 3"));
}

}  // namespace
