// Runs `cairn friction-dataset` and `cairn friction` as a user would.

#include <algorithm>
#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "run_cairn.h"
#include "test_paths.h"

namespace {

using cairn::test::CairnRun;
using cairn::test::RunCairn;

using ::testing::HasSubstr;
namespace fs = std::filesystem;

class FrictionCommandTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("cairn_friction_cli_" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    const CairnRun dataset =
        RunCairn("friction-dataset --out " + (dir_ / "data").string() + " --images 1 --width 96 --height 72");
    ASSERT_EQ(dataset.exit_code, 0) << dataset.output;
    image_ = (dir_ / "data" / "image_0000.png").string();
    ASSERT_TRUE(fs::exists(image_)) << dataset.output;
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
  std::string image_;
};

TEST_F(FrictionCommandTest, WritesLabelAndQuantileImagesAndStatistics) {
  for (const std::string& segmenter :
       {std::string("builtin"), std::string("onnx:") + CAIRN_SOURCE_DIR + "/data/models/tiny_material_net.yaml"}) {
    const fs::path out = dir_ / "out";
    const CairnRun run = RunCairn("friction --image " + image_ + " --segmenter " + segmenter + " --out " +
                                    out.string() + " --eta 0.9 --json");
    ASSERT_EQ(run.exit_code, 0) << run.output;
    EXPECT_THAT(run.output, HasSubstr("\"width\": 96, \"height\": 72"));
    EXPECT_THAT(run.output, HasSubstr("\"eta\": 0.9"));
    EXPECT_THAT(run.output, HasSubstr("\"label_fractions\": {\"asphalt\": "));
    EXPECT_TRUE(fs::exists(out / "materials.png"));
    EXPECT_TRUE(fs::exists(out / "friction.png"));
    std::ifstream json(out / "friction.json");
    std::stringstream text;
    text << json.rdbuf();
    EXPECT_EQ(text.str(), run.output);
    fs::remove_all(out);
  }
}

TEST_F(FrictionCommandTest, BadInputsExitWithOneAndSayWhy) {
  const std::string out = (dir_ / "out").string();
  CairnRun run = RunCairn("friction --image /nonexistent.png --out " + out);
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_THAT(run.output, HasSubstr("--image '/nonexistent.png' does not exist"));
  run = RunCairn("friction --image " + image_ + " --eta 1.5 --out " + out);
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_THAT(run.output, HasSubstr("--eta '1.5' is out of range; give a number from 1e-06 to 0.999999"));
  run = RunCairn("friction --image " + image_ + " --segmenter magic --out " + out);
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_THAT(run.output, HasSubstr("Unknown segmenter 'magic'"));
  run = RunCairn("friction --image " + image_);
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_THAT(run.output, HasSubstr("--out is required"));
}

TEST_F(FrictionCommandTest, AnImageTooLargeIsRefusedFromItsHeader) {
  // 33 bytes of PNG whose header claims 30000 x 30000 grey pixels (900 MB decoded): refused before decoding.
  const unsigned char header[] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n', 0, 0, 0, 13, 'I', 'H', 'D', 'R',
                                  0, 0, 0x75, 0x30, 0, 0, 0x75, 0x30, 8, 0, 0, 0, 0, 0, 0, 0, 0};
  const fs::path huge = dir_ / "huge.png";
  std::ofstream(huge, std::ios::binary).write(reinterpret_cast<const char*>(header), sizeof(header));
  const CairnRun run = RunCairn("friction --image " + huge.string() + " --out " + (dir_ / "out").string());
  EXPECT_EQ(run.exit_code, 1) << run.output;
  EXPECT_THAT(run.output, HasSubstr("image '" + huge.string() + "' is 30000 x 30000 = 900000000 pixels, more than "
                                    "the limit of 67108864 pixels; downscale or crop it"));
  EXPECT_EQ(std::count(run.output.begin(), run.output.end(), '\n'), 1) << run.output;
  EXPECT_FALSE(fs::exists(dir_ / "out"));
}

}  // namespace
