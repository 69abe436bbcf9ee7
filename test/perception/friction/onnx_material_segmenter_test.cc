#include "cairn/perception/friction/onnx_material_segmenter.h"

#include <cstdio>
#include <fstream>
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

#include "cairn/perception/evaluation/material_segmentation_score.h"
#include "cairn/perception/synthetic/material_scene.h"
#include "cairn/perception/synthetic/material_texture.h"
#include "expect_throws.h"
#include "test_paths.h"

namespace cairn::perception {
namespace {

const std::string kModelYaml = std::string(CAIRN_SOURCE_DIR) + "/data/models/tiny_material_net.yaml";
const std::string kModelOnnx = std::string(CAIRN_SOURCE_DIR) + "/data/models/tiny_material_net.onnx";

std::string TempPath(const std::string& name) {
  return std::string(CAIRN_BINARY_DIR) + "/onnx_material_segmenter_test_" + name;
}

void WriteText(const std::string& path, const std::string& text) { std::ofstream(path) << text; }

// A YAML for the committed model with the given label list and input block.
std::string Yaml(const std::string& labels, const std::string& input) {
  return "model: " + kModelOnnx + "\nlabels: [" + labels + "]\ninput:\n" + input;
}

const char* kInput = "  width: 160\n  height: 120\n  channel_order: rgb\n  mean: [127.5, 127.5, 127.5]\n"
                     "  scale: 0.00784313725490196\n";
const char* kLabels = "asphalt, grass, rock, carpet, ceramic, marble, metal, wood, sand, sky, snow, water, cloth, paper";

TEST(OnnxMaterialSegmenterTest, LoadsTheCommittedModel) {
  const OnnxMaterialSegmenter segmenter = OnnxMaterialSegmenter::Load(kModelYaml);
  EXPECT_EQ(segmenter.labels(), MaterialTexture::SupportedLabels());
  EXPECT_EQ(segmenter.preprocessing().width, 160);
  EXPECT_EQ(segmenter.preprocessing().height, 120);
  EXPECT_TRUE(segmenter.preprocessing().rgb);
  EXPECT_EQ(segmenter.model_path(), kModelOnnx);
}

TEST(OnnxMaterialSegmenterTest, SegmentsHeldOutRendersWellAboveChance) {
  const OnnxMaterialSegmenter segmenter = OnnxMaterialSegmenter::Load(kModelYaml);
  MaterialScene::Options options;
  options.width = 160;
  options.height = 120;
  options.noise_stddev = 2.0;
  const MaterialScene scene(options);
  MaterialSegmentationScore score(segmenter.num_labels());
  // The network was trained on seeds 1..240 (scripts/train_material_net.py); these scenes are new.
  for (std::uint32_t seed = 90000; seed < 90010; ++seed) {
    const MaterialScene::Rendering r = scene.Render(seed);
    const cv::Mat p = segmenter.Segment(r.image);  // Segment() checks that channels sum to 1 at every pixel.
    score.Add(p, r.labels);
  }
  std::printf("ONNX held-out pixel accuracy %.3f, class-average accuracy %.3f, ECE %.3f\n", score.pixel_accuracy(),
              score.class_average_accuracy(), score.expected_calibration_error());
  // Chance is 1/14. Measured 0.87 / 0.77 on these scenes (0.72 / 0.72 on the script's own held-out split); the
  // floors leave room for OpenCV dnn builds that round differently.
  EXPECT_GT(score.pixel_accuracy(), 0.75);
  EXPECT_GT(score.class_average_accuracy(), 0.65);
}

TEST(OnnxMaterialSegmenterTest, ResizesToAnyImageAndAcceptsGrey) {
  const OnnxMaterialSegmenter segmenter = OnnxMaterialSegmenter::Load(kModelYaml);
  const cv::Mat image(77, 203, CV_8UC3, cv::Scalar(40, 140, 60));
  const cv::Mat p = segmenter.Segment(image);
  EXPECT_EQ(p.size(), cv::Size(203, 77));
  EXPECT_EQ(p.type(), CV_32FC(14));
  const cv::Mat native = segmenter.SegmentNative(image);
  EXPECT_EQ(native.size(), cv::Size(40, 30));  // A quarter of the 160 x 120 input.
  const cv::Mat grey(50, 60, CV_8UC1, cv::Scalar(200));
  EXPECT_EQ(segmenter.Segment(grey).size(), cv::Size(60, 50));
  CAIRN_EXPECT_THROWS_WITH(segmenter.Segment(cv::Mat(4, 4, CV_8UC4)), std::invalid_argument, "4 channel(s)");
}

TEST(OnnxMaterialSegmenterTest, LabelMapMustMatchTheOutputChannels) {
  const std::string path = TempPath("thirteen.yaml");
  WriteText(path, Yaml("asphalt, grass, rock, carpet, ceramic, marble, metal, wood, sand, sky, snow, water, cloth",
                       kInput));
  CAIRN_EXPECT_THROWS_WITH(OnnxMaterialSegmenter::Load(path), std::invalid_argument, "has 13 labels",
                           "outputs 14 channels", "one label per output channel");
  std::remove(path.c_str());
}

TEST(OnnxMaterialSegmenterTest, BadFilesAndKeysAreNamed) {
  CAIRN_EXPECT_THROWS_WITH(OnnxMaterialSegmenter::Load("/nonexistent/net.yaml"), std::invalid_argument,
                           "Cannot read '/nonexistent/net.yaml'");
  const std::string path = TempPath("bad.yaml");
  WriteText(path, "labels: [a\n");
  CAIRN_EXPECT_THROWS_WITH(OnnxMaterialSegmenter::Load(path), std::invalid_argument, "Malformed YAML in");
  WriteText(path, "labels: [a, b]\n");
  CAIRN_EXPECT_THROWS_WITH(OnnxMaterialSegmenter::Load(path), std::invalid_argument, "line 1", "key 'model'", ".onnx");
  WriteText(path, "model: x.onnx\nlabels: []\n");
  CAIRN_EXPECT_THROWS_WITH(OnnxMaterialSegmenter::Load(path), std::invalid_argument, "key 'labels'", "non-empty");
  WriteText(path, Yaml(kLabels, "  width: 160\n  height: 120\n  channel_order: hsv\n"));
  CAIRN_EXPECT_THROWS_WITH(OnnxMaterialSegmenter::Load(path), std::invalid_argument, "input.channel_order",
                           "'rgb' or 'bgr'", "'hsv'");
  WriteText(path, Yaml(kLabels, "  width: 0\n  height: 120\n  channel_order: rgb\n"));
  CAIRN_EXPECT_THROWS_WITH(OnnxMaterialSegmenter::Load(path), std::invalid_argument, "line 4", "'input.width'",
                           "got '0'");
  WriteText(path, Yaml(kLabels, "  width: 160\n  height: 120\n  channel_order: rgb\n  mean: [1, 2]\n"));
  CAIRN_EXPECT_THROWS_WITH(OnnxMaterialSegmenter::Load(path), std::invalid_argument,
                           "'input.mean' must be a list of 3 numbers", "got '[1, 2]'");
  WriteText(path, Yaml(kLabels, "  width: 160\n  height: 120\n  channel_order: rgb\n  scale: -1\n"));
  CAIRN_EXPECT_THROWS_WITH(OnnxMaterialSegmenter::Load(path), std::invalid_argument, "input.scale", "-1");
  WriteText(path, Yaml(kLabels, "  width: wide\n  height: 120\n  channel_order: rgb\n"));
  CAIRN_EXPECT_THROWS_WITH(OnnxMaterialSegmenter::Load(path), std::invalid_argument, "'input.width' must be an integer",
                           "got 'wide'");
  WriteText(path, Yaml(kLabels, "  width: 160\n  heigth: 120\n  channel_order: rgb\n"));
  CAIRN_EXPECT_THROWS_WITH(OnnxMaterialSegmenter::Load(path), std::invalid_argument, "unknown key 'heigth'",
                           "Did you mean 'height'?");
  WriteText(path, "model: missing.onnx\nlabels: [a]\ninput: {width: 8, height: 8, channel_order: bgr}\n");
  CAIRN_EXPECT_THROWS_WITH(OnnxMaterialSegmenter::Load(path), std::runtime_error, "missing.onnx",
                           "cannot be opened", "relative paths start at the YAML's folder");
  const std::string garbage = TempPath("garbage.onnx");
  WriteText(garbage, "this is not a protobuf");
  WriteText(path, "model: " + garbage + "\nlabels: [a]\ninput: {width: 8, height: 8, channel_order: bgr}\n");
  try {
    OnnxMaterialSegmenter::Load(path);
    ADD_FAILURE() << "a garbage ONNX file was loaded";
  } catch (const std::runtime_error& error) {
    // One line naming the file; none of OpenCV's multi-line text (its sources, "error: (-2:...)").
    const std::string message = error.what();
    EXPECT_NE(message.find(garbage), std::string::npos) << message;
    EXPECT_NE(message.find("not an ONNX network OpenCV can read"), std::string::npos) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    EXPECT_EQ(message.find("error: ("), std::string::npos) << message;
  }
  WriteText(path, "model: " + garbage + "\nlabels: [a]\ninput: {width: 30000, height: 30000, channel_order: bgr}\n");
  CAIRN_EXPECT_THROWS_WITH(OnnxMaterialSegmenter::Load(path), std::invalid_argument, "line 3",
                           "'input.width' and 'input.height' give 30000x30000 pixels",
                           "more than the 67108864");
  WriteText(path, "model: " + garbage + "\nlabels: [a]\ninput: {width: 8, height: 8, channel_order: bgr, "
                  "mean: [0, .nan, 0]}\n");
  CAIRN_EXPECT_THROWS_WITH(OnnxMaterialSegmenter::Load(path), std::invalid_argument, "input.mean", "finite");
  std::remove(garbage.c_str());
  std::remove(path.c_str());
}

}  // namespace
}  // namespace cairn::perception
