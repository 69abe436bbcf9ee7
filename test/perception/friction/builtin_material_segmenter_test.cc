#include "cairn/perception/friction/builtin_material_segmenter.h"

#include <cstdio>
#include <fstream>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "cairn/perception/evaluation/material_segmentation_score.h"
#include "cairn/perception/synthetic/material_scene.h"
#include "cairn/perception/synthetic/material_texture.h"
#include "expect_throws.h"
#include "test_paths.h"

namespace cairn::perception {
namespace {

MaterialScene Scene() {
  MaterialScene::Options options;
  options.width = 192;
  options.height = 144;
  options.noise_stddev = 2.0;
  return MaterialScene(options);
}

struct TrainingSet {
  std::vector<cv::Mat> images;
  std::vector<cv::Mat> labels;
};

TrainingSet Renders(std::uint32_t first_seed, int count) {
  const MaterialScene scene = Scene();
  TrainingSet set;
  for (int i = 0; i < count; ++i) {
    MaterialScene::Rendering r = scene.Render(first_seed + static_cast<std::uint32_t>(i));
    set.images.push_back(r.image);
    set.labels.push_back(r.labels);
  }
  return set;
}

BuiltinMaterialSegmenter::TrainingOptions Options() {
  BuiltinMaterialSegmenter::TrainingOptions options;
  options.epochs = 30;
  return options;
}

std::string TempPath(const std::string& name) {
  return std::string(CAIRN_BINARY_DIR) + "/builtin_material_segmenter_test_" + name;
}

// One training (about 2 s) shared by the tests that only read the model.
class BuiltinMaterialSegmenterTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    const TrainingSet set = Renders(1, 24);
    report_ = new BuiltinMaterialSegmenter::TrainingReport;
    segmenter_ = new BuiltinMaterialSegmenter(BuiltinMaterialSegmenter::Train(
        MaterialTexture::SupportedLabels(), set.images, set.labels, Options(), report_));
  }
  static void TearDownTestSuite() {
    delete segmenter_;
    delete report_;
  }
  static BuiltinMaterialSegmenter* segmenter_;
  static BuiltinMaterialSegmenter::TrainingReport* report_;
};
BuiltinMaterialSegmenter* BuiltinMaterialSegmenterTest::segmenter_ = nullptr;
BuiltinMaterialSegmenter::TrainingReport* BuiltinMaterialSegmenterTest::report_ = nullptr;

TEST_F(BuiltinMaterialSegmenterTest, AccurateOnHeldOutRenders) {
  // Held-out scenes: seeds far from the training ones. Measured 0.77 / 0.77 (chance: 0.07); the floors leave
  // room for floating-point differences across compilers.
  const TrainingSet test = Renders(50000, 8);
  MaterialSegmentationScore score(segmenter_->num_labels());
  for (std::size_t i = 0; i < test.images.size(); ++i) score.Add(segmenter_->Segment(test.images[i]), test.labels[i]);
  std::printf("held-out pixel accuracy %.3f, class-average accuracy %.3f, ECE %.3f\n", score.pixel_accuracy(),
              score.class_average_accuracy(), score.expected_calibration_error());
  EXPECT_GT(score.pixel_accuracy(), 0.70);
  EXPECT_GT(score.class_average_accuracy(), 0.65);
  // The chance level of 14 labels is 0.07: the classifier is far from guessing.
  EXPECT_GT(report_->training_accuracy, 0.9);
}

TEST_F(BuiltinMaterialSegmenterTest, ProbabilitiesAreCalibrated) {
  EXPECT_GT(report_->temperature, 0.05);
  EXPECT_LT(report_->temperature, 20.0);
  // Temperature scaling minimises the calibration NLL, so it cannot be worse than T = 1 there.
  EXPECT_LE(report_->nll_after, report_->nll_before + 1e-9);
  EXPECT_LT(report_->ece_after, 0.1);
  // On scenes it has never seen the reliability holds too.
  const TrainingSet test = Renders(60000, 6);
  MaterialSegmentationScore score(segmenter_->num_labels());
  for (std::size_t i = 0; i < test.images.size(); ++i) score.Add(segmenter_->Segment(test.images[i]), test.labels[i]);
  std::printf("calibration: T %.3f, ECE %.3f -> %.3f on the calibration split, %.3f on new scenes\n",
              report_->temperature, report_->ece_before, report_->ece_after, score.expected_calibration_error());
  EXPECT_LT(score.expected_calibration_error(), 0.12);
}

TEST_F(BuiltinMaterialSegmenterTest, OutputShapesAndGreyImages) {
  const TrainingSet test = Renders(70000, 1);
  const cv::Mat grid = segmenter_->SegmentGrid(test.images[0]);
  EXPECT_EQ(grid.size(), cv::Size(24, 18));
  EXPECT_EQ(grid.type(), CV_32FC(14));
  const cv::Mat odd = test.images[0](cv::Rect(5, 3, 101, 67)).clone();
  const cv::Mat p = segmenter_->Segment(odd);  // Segment() checks the channels sum to 1 at every pixel.
  EXPECT_EQ(p.size(), cv::Size(101, 67));
  cv::Mat grey;
  cv::extractChannel(test.images[0], grey, 1);
  EXPECT_EQ(segmenter_->Segment(grey).type(), CV_32FC(14));
  CAIRN_EXPECT_THROWS_WITH(segmenter_->Segment(cv::Mat(8, 8, CV_16UC1)), std::invalid_argument, "8-bit");
  const int window = segmenter_->features().window();
  CAIRN_EXPECT_THROWS_WITH(segmenter_->Segment(test.images[0](cv::Rect(0, 0, 64, window - 1)).clone()),
                           std::invalid_argument, "64x" + std::to_string(window - 1), "smaller than the segmenter's");
}

TEST_F(BuiltinMaterialSegmenterTest, SaveLoadRoundTrip) {
  const std::string path = TempPath("roundtrip.yaml");
  segmenter_->Save(path);
  const BuiltinMaterialSegmenter loaded = BuiltinMaterialSegmenter::Load(path);
  EXPECT_EQ(loaded.labels(), segmenter_->labels());
  EXPECT_NEAR(loaded.temperature(), segmenter_->temperature(), 1e-12);
  EXPECT_EQ(loaded.hidden_units(), segmenter_->hidden_units());
  const TrainingSet test = Renders(80000, 1);
  EXPECT_LT(cv::norm(loaded.Segment(test.images[0]), segmenter_->Segment(test.images[0]), cv::NORM_INF), 1e-5);
  std::remove(path.c_str());
}

TEST(BuiltinMaterialSegmenterTrainTest, TrainingIsDeterministic) {
  const TrainingSet set = Renders(100, 4);
  BuiltinMaterialSegmenter::TrainingOptions options = Options();
  options.epochs = 3;
  const std::vector<std::string> labels = MaterialTexture::SupportedLabels();
  const auto a = BuiltinMaterialSegmenter::Train(labels, set.images, set.labels, options);
  const auto b = BuiltinMaterialSegmenter::Train(labels, set.images, set.labels, options);
  EXPECT_EQ(cv::norm(a.SegmentGrid(set.images[0]), b.SegmentGrid(set.images[0]), cv::NORM_INF), 0.0);
  options.seed = 2;
  const auto c = BuiltinMaterialSegmenter::Train(labels, set.images, set.labels, options);
  EXPECT_GT(cv::norm(a.SegmentGrid(set.images[0]), c.SegmentGrid(set.images[0]), cv::NORM_INF), 0.0);
}

TEST(BuiltinMaterialSegmenterTrainTest, BadTrainingInputsAreNamed) {
  const TrainingSet set = Renders(200, 2);
  const std::vector<std::string> labels = MaterialTexture::SupportedLabels();
  const auto options = Options();
  CAIRN_EXPECT_THROWS_WITH(BuiltinMaterialSegmenter::Train(labels, set.images, {set.labels[0]}, options),
                           std::invalid_argument, "2 images but 1 label images");
  CAIRN_EXPECT_THROWS_WITH(BuiltinMaterialSegmenter::Train(labels, {set.images[0]}, {set.labels[0]}, options),
                           std::invalid_argument, "at least 2 images", "got 1");
  cv::Mat bad_label = set.labels[1].clone();
  bad_label.at<std::uint8_t>(3, 5) = 40;
  CAIRN_EXPECT_THROWS_WITH(BuiltinMaterialSegmenter::Train(labels, set.images, {set.labels[0], bad_label}, options),
                           std::invalid_argument, "label image 1 holds 40 at pixel (3, 5)", "or 255");
  cv::Mat wide_label;
  set.labels[1].convertTo(wide_label, CV_16U);
  CAIRN_EXPECT_THROWS_WITH(BuiltinMaterialSegmenter::Train(labels, set.images, {set.labels[0], wide_label}, options),
                           std::invalid_argument, "label image 1 must be CV_8UC1");
  CAIRN_EXPECT_THROWS_WITH(
      BuiltinMaterialSegmenter::Train(labels, {set.images[0], cv::Mat(4, 4, CV_32FC3)}, set.labels, options),
      std::invalid_argument, "image 1 must be a non-empty 8-bit image");
  auto bad = options;
  bad.calibration_fraction = 1.0;
  CAIRN_EXPECT_THROWS_WITH(BuiltinMaterialSegmenter::Train(labels, set.images, set.labels, bad),
                           std::invalid_argument, "calibration_fraction", "got 1");
  bad = options;
  bad.epochs = 0;
  CAIRN_EXPECT_THROWS_WITH(BuiltinMaterialSegmenter::Train(labels, set.images, set.labels, bad),
                           std::invalid_argument, "epochs", "0");
  bad = options;
  bad.learning_rate = -1.0;
  CAIRN_EXPECT_THROWS_WITH(BuiltinMaterialSegmenter::Train(labels, set.images, set.labels, bad),
                           std::invalid_argument, "learning_rate", "-1");
  const cv::Mat none(set.labels[0].size(), CV_8UC1, cv::Scalar(255));
  CAIRN_EXPECT_THROWS_WITH(BuiltinMaterialSegmenter::Train(labels, set.images, {none, set.labels[1]}, options),
                           std::invalid_argument, "no labelled patch centre");
  {
    auto many = options;
    many.hidden_units = 5000;
    CAIRN_EXPECT_THROWS_WITH(BuiltinMaterialSegmenter::Train(labels, set.images, set.labels, many),
                             std::invalid_argument, "hidden_units 5000", "4096");
    std::vector<cv::Mat> small = set.images;
    std::vector<cv::Mat> small_labels = set.labels;
    small[1] = small[1](cv::Rect(0, 0, options.window - 2, 40)).clone();
    small_labels[1] = small_labels[1](cv::Rect(0, 0, options.window - 2, 40)).clone();
    CAIRN_EXPECT_THROWS_WITH(BuiltinMaterialSegmenter::Train(labels, small, small_labels, options),
                             std::invalid_argument, "image 1 is " + std::to_string(options.window - 2) + "x40",
                             "smaller than the");
  }
  CAIRN_EXPECT_THROWS_WITH(BuiltinMaterialSegmenter::Train({"a", "a"}, set.images, set.labels, options),
                           std::invalid_argument, "'a' appears twice");
}

void WriteText(const std::string& path, const std::string& text) { std::ofstream(path) << text; }

TEST(BuiltinMaterialSegmenterLoadTest, BadFilesGiveClearErrors) {
  CAIRN_EXPECT_THROWS_WITH(BuiltinMaterialSegmenter::Load("/nonexistent/model.yaml"), std::invalid_argument,
                           "Cannot read '/nonexistent/model.yaml'", "cairn friction-train --out");
  const std::string path = TempPath("bad.yaml");
  WriteText(path, "format: [unclosed\n");
  CAIRN_EXPECT_THROWS_WITH(BuiltinMaterialSegmenter::Load(path), std::invalid_argument, "Malformed YAML in", "line");
  WriteText(path, "format: something_else\nversion: 1\n");
  CAIRN_EXPECT_THROWS_WITH(BuiltinMaterialSegmenter::Load(path), std::invalid_argument,
                           "not a built-in material segmenter model");
  WriteText(path, "format: cairn_builtin_material_segmenter\nversion: 9\n");
  CAIRN_EXPECT_THROWS_WITH(BuiltinMaterialSegmenter::Load(path), std::invalid_argument, "line 2", "has version 9",
                           "reads version 1");
  WriteText(path, "format: cairn_builtin_material_segmenter\nversion: 1\nlabels: [a, b]\nwindow: 15\n");
  CAIRN_EXPECT_THROWS_WITH(BuiltinMaterialSegmenter::Load(path), std::invalid_argument, "missing key 'stride'");

  // A real model, truncated: its weight matrices lose values.
  const TrainingSet set = Renders(300, 2);
  auto options = Options();
  options.epochs = 1;
  options.hidden_units = 4;
  BuiltinMaterialSegmenter::Train(MaterialTexture::SupportedLabels(), set.images, set.labels, options).Save(path);
  std::ifstream in(path);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const auto w2 = text.find("w2:");
  ASSERT_NE(w2, std::string::npos);
  const auto data = text.find("data: [", w2) + 7;
  std::string broken = text;
  broken.replace(data, text.find(']', data) - data, "1.5");  // w2 keeps one value of its 56.
  WriteText(path, broken);
  CAIRN_EXPECT_THROWS_WITH(BuiltinMaterialSegmenter::Load(path), std::invalid_argument, "malformed 'w2'",
                           "got rows 14, cols 4 and 1 values");
  std::string wrong_type = text;
  wrong_type.replace(wrong_type.find("temperature: "), 13, "temperature: warm #");
  WriteText(path, wrong_type);
  CAIRN_EXPECT_THROWS_WITH(BuiltinMaterialSegmenter::Load(path), std::invalid_argument,
                           "'temperature' must be a number, got 'warm'", "line");
  std::string negative = text;
  negative.replace(negative.find("temperature: "), 13, "temperature: -");
  WriteText(path, negative);
  CAIRN_EXPECT_THROWS_WITH(BuiltinMaterialSegmenter::Load(path), std::invalid_argument, "temperature -",
                           "must be positive");
  // Sizes a file states are bounded before anything is allocated from them.
  std::string hidden = text;
  const auto b1 = hidden.find("b1:");
  const auto cols = hidden.find("cols: ", b1) + 6;
  hidden.replace(cols, hidden.find_first_of(",}\n", cols) - cols, "100000000");
  WriteText(path, hidden);
  CAIRN_EXPECT_THROWS_WITH(BuiltinMaterialSegmenter::Load(path), std::invalid_argument, "100000000 hidden units",
                           "[1, 4096]");
  std::string window = text;
  window.replace(window.find("window: "), 8, "window: 4001 #");
  WriteText(path, window);
  CAIRN_EXPECT_THROWS_WITH(BuiltinMaterialSegmenter::Load(path), std::invalid_argument, "inconsistent",
                           "[3, 1023]", "got 4001", "Re-create it");
  std::remove(path.c_str());
}

TEST(BuiltinMaterialSegmenterLoadTest, SaveToAnUnwritablePathNamesIt) {
  const TrainingSet set = Renders(400, 2);
  auto options = Options();
  options.epochs = 1;
  const auto segmenter =
      BuiltinMaterialSegmenter::Train(MaterialTexture::SupportedLabels(), set.images, set.labels, options);
  CAIRN_EXPECT_THROWS_WITH(segmenter.Save("/nonexistent/folder/model.yaml"), std::runtime_error,
                           "/nonexistent/folder/model.yaml");
}

}  // namespace
}  // namespace cairn::perception
