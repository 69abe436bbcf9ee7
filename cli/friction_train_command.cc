// `cairn friction-train`: trains the built-in material segmenter on rendered material scenes, scores it on
// held-out renders (pixel and class-average accuracy, calibration) and saves the model.

#include <chrono>
#include <cstdint>
#include <cstdio>
#include <functional>
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "cairn/common/json_writer.h"
#include "cairn/common/number_text.h"
#include "cairn/perception/evaluation/material_segmentation_score.h"
#include "cairn/perception/friction/builtin_material_segmenter.h"
#include "cairn/perception/synthetic/material_scene.h"
#include "cairn/perception/synthetic/stereo_material_scene.h"
#include "choice_option.h"
#include "command_registry.h"
#include "file_checks.h"
#include "numeric_option.h"
#include "usage_error.h"

namespace cairn::cli {
namespace {

struct FrictionTrainState {
  std::string out;
  int images{60};
  int test_images{40};
  unsigned seed{1};
  int width{320};
  int height{240};
  double noise{2.0};
  int epochs{40};
  int hidden{48};
  std::string source{"material"};
  bool json{false};
};

// Held-out scenes use seeds far from the training ones, so no test scene is a training scene.
constexpr unsigned kTestSeedOffset = 1000000u;

// Option ranges (--help states them). Sides from the 15-pixel patch the segmenter classifies to a 4K frame;
// image counts below the test seed offset, so training and test seeds never meet.
constexpr int kMinSide = 16;
constexpr int kMaxSide = 4096;
constexpr int kMaxImages = 100000;
// Training renders held at once (colour and labels: 4 bytes a pixel, 1 GiB in all).
constexpr double kMaxTrainingPixels = 268435456.0;

int RunFrictionTrain(const FrictionTrainState& s) {
  using namespace cairn::perception;
  // Training scene i uses seed + i, test scene i seed + kTestSeedOffset + i (the larger, as --images is below the
  // offset): a sum past 2^32 - 1 would wrap round onto other seeds, the training ones among them.
  constexpr std::uint64_t kMaxSeed = std::numeric_limits<unsigned>::max();
  const std::uint64_t last_seed =
      std::uint64_t{s.seed} + kTestSeedOffset + static_cast<std::uint64_t>(s.test_images) - 1;
  if (last_seed > kMaxSeed) {
    throw UsageError("--seed " + cairn::FormatShort(s.seed) + " with --test-images " + cairn::FormatShort(s.test_images) +
                     " would use seeds up to " + cairn::FormatShort(last_seed) + " (test scenes start " +
                     cairn::FormatShort(kTestSeedOffset) + " after the seed), past " + cairn::FormatShort(kMaxSeed) +
                     "; give --seed at most " +
                     cairn::FormatShort(kMaxSeed - kTestSeedOffset - static_cast<std::uint64_t>(s.test_images) + 1));
  }
  // The training renders are all held in memory: bound their pixels before rendering any.
  const double pixels = static_cast<double>(s.images) * s.width * s.height;
  if (pixels > kMaxTrainingPixels) {
    throw UsageError("--images " + cairn::FormatShort(s.images) + " of " + cairn::FormatShort(s.width) + "x" +
                     cairn::FormatShort(s.height) + " pixels is " + FormatShort(pixels) +
                     " pixels to hold in memory, more than the limit of " +
                     cairn::FormatShort(static_cast<long long>(kMaxTrainingPixels)) +
                     "; use fewer or smaller images");
  }
  // Before the training: an --out that cannot be written fails now, not minutes later.
  CheckOutputFile("--out", s.out);
  // Scene i of the chosen family as (colour image, label-index image).
  std::vector<std::string> labels;
  std::function<std::pair<cv::Mat, cv::Mat>(unsigned)> render;
  if (s.source == "material") {
    MaterialScene::Options scene_options;
    scene_options.width = s.width;
    scene_options.height = s.height;
    scene_options.noise_stddev = s.noise;
    auto scene = std::make_shared<const MaterialScene>(scene_options);
    labels = scene->options().labels;
    render = [scene](unsigned seed) {
      MaterialScene::Rendering r = scene->Render(seed);
      return std::make_pair(r.image, r.labels);
    };
  } else if (s.source == "stereo") {
    StereoMaterialScene::Options scene_options;
    scene_options.width = s.width;
    scene_options.height = s.height;
    scene_options.noise_variance = s.noise * s.noise;
    auto scene = std::make_shared<const StereoMaterialScene>(scene_options);
    labels = scene->options().labels;
    render = [scene](unsigned seed) {
      StereoMaterialScene::Rendering r = scene->Render(seed);
      return std::make_pair(r.image, r.labels);
    };
  } else {
    throw std::logic_error("--source '" + s.source + "' passed its check");  // AddChoiceOption refuses it
  }

  const auto start = std::chrono::steady_clock::now();
  std::vector<cv::Mat> images;
  std::vector<cv::Mat> label_images;
  for (int i = 0; i < s.images; ++i) {
    auto [image, label_image] = render(s.seed + static_cast<unsigned>(i));
    images.push_back(image);
    label_images.push_back(label_image);
  }
  BuiltinMaterialSegmenter::TrainingOptions options;
  options.epochs = s.epochs;
  options.hidden_units = s.hidden;
  options.seed = s.seed;
  BuiltinMaterialSegmenter::TrainingReport report;
  const BuiltinMaterialSegmenter segmenter =
      BuiltinMaterialSegmenter::Train(labels, images, label_images, options, &report);
  const double train_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  segmenter.Save(s.out);

  MaterialSegmentationScore score(static_cast<int>(labels.size()));
  double segment_ms = 0.0;
  for (int i = 0; i < s.test_images; ++i) {
    const auto [image, label_image] = render(s.seed + kTestSeedOffset + static_cast<unsigned>(i));
    const auto t0 = std::chrono::steady_clock::now();
    const cv::Mat probabilities = segmenter.Segment(image);
    segment_ms += std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    score.Add(probabilities, label_image);
  }
  segment_ms /= s.test_images;

  std::vector<double> per_label(labels.size(), -1.0);
  for (std::size_t k = 0; k < labels.size(); ++k) {
    const auto total = score.confusion().row(static_cast<Eigen::Index>(k)).sum();
    if (total > 0) {
      per_label[k] = static_cast<double>(score.confusion()(static_cast<Eigen::Index>(k), static_cast<Eigen::Index>(k))) /
                     static_cast<double>(total);
    }
  }
  if (s.json) {
    const JsonWriter::NumberFormat f2 = JsonWriter::Fixed(2);
    const JsonWriter::NumberFormat f4 = JsonWriter::Fixed(4);
    JsonWriter json;
    json.BeginObject().Key("model").String(s.out).Key("source").String(s.source);
    json.Key("train_images").Integer(s.images).Key("test_images").Integer(s.test_images);
    json.Key("width").Integer(s.width).Key("height").Integer(s.height).Key("train_seconds").Number(train_s, f2);
    json.Key("training_samples").Integer(report.num_training_samples);
    json.Key("calibration_samples").Integer(report.num_calibration_samples);
    json.Key("temperature").Number(report.temperature, f4);
    json.Key("calibration_ece_before").Number(report.ece_before, f4);
    json.Key("calibration_ece_after").Number(report.ece_after, f4);
    json.Key("test_pixel_accuracy").Number(score.pixel_accuracy(), f4);
    json.Key("test_class_average_accuracy").Number(score.class_average_accuracy(), f4);
    json.Key("test_ece").Number(score.expected_calibration_error(), f4);
    json.Key("test_nll").Number(score.mean_negative_log_likelihood(), f4);
    json.Key("segment_ms_per_image").Number(segment_ms, f2).Key("per_label_accuracy").BeginObject();
    for (std::size_t k = 0; k < labels.size(); ++k) {
      if (per_label[k] >= 0.0) json.Key(labels[k]).Number(per_label[k], f4);
    }
    std::printf("%s\n", json.EndObject().EndObject().text().c_str());
  } else {
    std::printf("trained on %d %s renders (%dx%d) in %.1f s: %d patches, %d calibration patches\n", s.images,
                s.source.c_str(), s.width, s.height, train_s, report.num_training_samples,
                report.num_calibration_samples);
    std::printf("calibration: temperature %.3f, ECE %.3f -> %.3f, NLL %.3f -> %.3f\n", report.temperature,
                report.ece_before, report.ece_after, report.nll_before, report.nll_after);
    std::printf("held-out %d renders: pixel accuracy %.3f, class-average accuracy %.3f, ECE %.3f "
                "(thesis SegNet on real photos: 0.79 / 0.48); %.1f ms per image\n",
                s.test_images, score.pixel_accuracy(), score.class_average_accuracy(),
                score.expected_calibration_error(), segment_ms);
    for (std::size_t k = 0; k < labels.size(); ++k) {
      if (per_label[k] >= 0.0) std::printf("  %-8s %.3f\n", labels[k].c_str(), per_label[k]);
    }
    std::printf("model written to %s\n", s.out.c_str());
  }
  return 0;
}

}  // namespace

void RegisterFrictionTrainCommand(CommandRegistry* registry) {
  registry->Add("friction-train", "Train the built-in material segmenter on rendered scenes and score it",
                [](CLI::App& app) -> CommandAction {
                  auto s = std::make_shared<FrictionTrainState>();
                  app.add_option("--out", s->out, "Model file to write (YAML)")->required();
                  AddNumberOption(app, "--images", &s->images, "Training renders (the last quarter calibrates)",
                                  NumberRange::Closed(2, kMaxImages));
                  AddNumberOption(app, "--test-images", &s->test_images, "Held-out renders to score on",
                                  NumberRange::Closed(1, kMaxImages));
                  AddNumberOption(app, "--seed", &s->seed, "Seed of the first training scene and of training",
                                  NumberRange::Closed(0, 4294967295.0));
                  AddNumberOption(app, "--width", &s->width, "Render width", NumberRange::Closed(kMinSide, kMaxSide));
                  AddNumberOption(app, "--height", &s->height, "Render height",
                                  NumberRange::Closed(kMinSide, kMaxSide));
                  AddNumberOption(app, "--noise", &s->noise, "Gaussian noise standard deviation (0..255)",
                                  NumberRange::Closed(0.0, 255.0));
                  AddNumberOption(app, "--epochs", &s->epochs, "Training passes", NumberRange::Closed(1, 10000));
                  AddNumberOption(app, "--hidden", &s->hidden, "Hidden units", NumberRange::Closed(1, 4096));
                  AddChoiceOption(app, "--source", &s->source,
                                  "Scene renderer: 'material' (MaterialScene) or 'stereo' (the synthetic stereo "
                                  "source, StereoMaterialScene); --noise is the standard deviation for both",
                                  {"material", "stereo"});
                  app.add_flag("--json", s->json, "Print one JSON object");
                  return [s] { return RunFrictionTrain(*s); };
                });
}

}  // namespace cairn::cli
