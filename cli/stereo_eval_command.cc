// `cairn stereo-eval`: matches one rectified pair, computes whole-range confidence and scores it against ground
// truth with the thesis' criteria (section 4.3.4).

#include <chrono>
#include <cctype>
#include <cstdio>
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "cairn/common/json_writer.h"
#include "cairn/perception/evaluation/middlebury_pair.h"
#include "cairn/perception/evaluation/stereo_evaluation.h"
#include "cairn/perception/io/image_file.h"
#include "cairn/perception/stereo/compute_confidence.h"
#include "cairn/perception/stereo/compute_cost_volume.h"
#include "cairn/perception/stereo/cost_samples.h"
#include "cairn/perception/stereo/winner_take_all.h"
#include "cairn/common/number_text.h"
#include "choice_option.h"
#include "command_registry.h"
#include "file_checks.h"
#include "numeric_option.h"
#include "quiet_stderr.h"
#include "usage_error.h"

namespace cairn::cli {
namespace {

// Option ranges (--help states them). Disparities and borders beyond these exceed any image the loaders take;
// the image-dependent limits (a range wider than the image) are the stereo library's.
constexpr int kMaxDisparity = 4095;
constexpr int kMaxBorder = 10000;
constexpr double kMaxParameter = 1e12;

struct StereoEvalState {
  std::string left;
  std::string right;
  std::string gt;
  std::string gt_right;
  // Absent options are not sentinel values: a flag given, with whatever value, is never taken for "automatic".
  double gt_scale{0.0};
  bool gt_scale_given{false};
  int dmax{0};
  bool dmax_given{false};
  std::string cost{"btsad"};
  int window{9};
  std::string model{"merrell"};
  std::string params{"ml"};
  std::string prefilter{"sobel"};
  int border{10};
  bool json{false};
};

double MillisecondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

int RunStereoEval(const StereoEvalState& s) {
  using namespace cairn::perception;
  // Parse the names first: a typo should fail before any image is read.
  const CostFunction cost = ParseCostFunction(s.cost);
  const ConfidenceModelType model_type = ParseConfidenceModelType(s.model);
  const Prefilter prefilter = ParsePrefilter(s.prefilter);
  double fixed_parameter = 0.0;
  const bool ml = s.params == "ml";
  const bool from_gt = s.params == "gt";
  if (!ml && !from_gt) {
    // A value of the model's parameter (a variance or a scale of costs), else the ways to fit it.
    try {
      fixed_parameter = ParseNumber<double>("--params", s.params, NumberRange::AboveAtMost(0.0, kMaxParameter));
    } catch (const UsageError&) {
      if (!s.params.empty() && (std::isdigit(static_cast<unsigned char>(s.params[0])) || s.params[0] == '-' ||
                                s.params[0] == '.' || s.params[0] == '+')) {
        throw;
      }
      throw UsageError("--params '" + s.params + "' is neither 'ml', 'gt' nor a number; e.g. --params ml or "
                       "--params 8.49e1");
    }
  }
  CheckInputFile("--left", s.left, "an image file");
  CheckInputFile("--right", s.right, "an image file");
  CheckInputFile("--gt", s.gt, "an image file");
  if (!s.gt_right.empty()) CheckInputFile("--gt-right", s.gt_right, "an image file");
  if (!s.gt_scale_given && ReadImageFileInfo(s.gt).bit_depth != 16) {
    // A 16-bit (KITTI) file states its scale; 8-bit Middlebury files do not, and theirs differ per data set.
    throw UsageError("--gt-scale is needed: the ground truth '" + s.gt + "' is 8-bit, whose scale differs per "
                     "data set (Middlebury 2001: --gt-scale 8, tsukuba 16, 2003 quarter size 4, 2005-2006 third "
                     "size 3)");
  }
  // libpng prints its own complaint about a corrupt file before the loader reports it.
  cv::Mat left, right, gt, gt_right;
  {
    const QuietStderr quiet;
    left = LoadGrayImage(s.left);
    right = LoadGrayImage(s.right);
    gt = s.gt_scale_given ? LoadDisparityImage(s.gt, s.gt_scale) : LoadDisparityImage(s.gt);
    if (!s.gt_right.empty()) {
      gt_right = s.gt_scale_given ? LoadDisparityImage(s.gt_right, s.gt_scale) : LoadDisparityImage(s.gt_right);
    }
  }
  if (left.size() != right.size()) {
    throw std::invalid_argument("left image '" + s.left + "' is " + cairn::FormatShort(left.cols) + "x" +
                                cairn::FormatShort(left.rows) + " but right image '" + s.right + "' is " +
                                cairn::FormatShort(right.cols) + "x" + cairn::FormatShort(right.rows) +
                                "; pass a rectified pair of equal size");
  }
  if (gt.size() != left.size()) {
    throw std::invalid_argument("ground truth '" + s.gt + "' is " + cairn::FormatShort(gt.cols) + "x" +
                                cairn::FormatShort(gt.rows) + " but the images are " + cairn::FormatShort(left.cols) + "x" +
                                cairn::FormatShort(left.rows) + "; pass the left view's disparity map");
  }
  cv::Mat occluded;
  if (!s.gt_right.empty()) {
    if (gt_right.size() != gt.size()) {
      throw std::invalid_argument("right ground truth '" + s.gt_right + "' differs in size from '" + s.gt + "'");
    }
    occluded = OcclusionFromGroundTruth(gt, gt_right);
  }
  CostVolumeOptions options;
  options.cost = cost;
  options.window = s.window;
  options.prefilter = prefilter;
  options.min_disparity = 0;
  // Default: the ground truth's largest disparity, rounded up to a multiple of 16 as block matchers expect.
  options.max_disparity = s.dmax_given ? s.dmax : AutomaticMaxDisparity(gt);

  auto start = std::chrono::steady_clock::now();
  DisparityVolume costs;
  ComputeCostVolume(left, right, options, &costs);
  const double ms_cost_volume = MillisecondsSince(start);
  start = std::chrono::steady_clock::now();
  WtaResult wta;
  ComputeWinnerTakeAll(costs, WtaOptions{}, &wta);
  const double ms_wta = MillisecondsSince(start);

  start = std::chrono::steady_clock::now();
  std::vector<float> samples;
  std::optional<ConfidenceModel> model;
  if (ml || from_gt) {
    if (ml) {
      CollectConsistentWtaCosts(costs, wta, &samples);
    } else {
      cv::Mat visible;
      if (!occluded.empty()) cv::compare(occluded, 0, visible, cv::CMP_EQ);
      CollectGroundTruthCosts(costs, gt, visible, &samples);
    }
    model = ConfidenceModel::FitMaximumLikelihood(model_type, cost, samples);
  } else {
    model = ConfidenceModel::Parametric(model_type, cost, fixed_parameter);
  }
  DisparityVolume confidence;
  ComputeConfidence(costs, *model, &confidence);
  const double ms_confidence = MillisecondsSince(start);

  StereoEvaluationOptions evaluation_options;
  evaluation_options.border = s.border;
  const StereoEvaluation result = EvaluateStereo(confidence, wta, gt, occluded, evaluation_options);
  const double parameter = model->parameter();
  if (s.json) {
    const JsonWriter::NumberFormat f3 = JsonWriter::Fixed(3);
    const JsonWriter::NumberFormat f6 = JsonWriter::Fixed(6);
    JsonWriter json;
    json.BeginObject().Key("bad_pixel_rate").Number(result.bad_pixel_rate, f6);
    json.Key("bad_pixel_rate_subpixel").Number(result.bad_pixel_rate_subpixel, f6);
    json.Key("auc").Number(result.auc, f6).Key("auc_optimal").Number(result.auc_optimal, f6);
    json.Key("c_gt_badpx").Number(result.c_gt_badpx, f6);
    // Nine significant digits: "%f" wrote a parameter of 1e-300 as 0.000000. The histogram model's NaN is null.
    json.Key("parameter").Number(parameter, JsonWriter::Significant(9));
    json.Key("model").String(s.model).Key("cost").String(s.cost).Key("window").Integer(s.window);
    json.Key("max_disparity").Integer(options.max_disparity).Key("pixels").Integer(result.num_pixels);
    json.Key("ms_cost_volume").Number(ms_cost_volume, f3).Key("ms_wta").Number(ms_wta, f3);
    json.Key("ms_confidence").Number(ms_confidence, f3).EndObject();
    std::printf("%s\n", json.text().c_str());
  } else {
    std::printf("model            %s\n", model->Describe().c_str());
    std::printf("disparities      0..%d, %s %dx%d, prefilter %s\n", options.max_disparity, s.cost.c_str(), s.window,
                s.window, s.prefilter.c_str());
    std::printf("pixels           %zu evaluated, %zu bad\n", result.num_pixels, result.num_bad);
    std::printf("bad-pixel rate   %.4f (sub-pixel WTA: %.4f)\n", result.bad_pixel_rate, result.bad_pixel_rate_subpixel);
    std::printf("AUC              %.4f (optimal %.4f)\n", result.auc, result.auc_optimal);
    std::printf("C(d in GT)_badpx %.4f\n", result.c_gt_badpx);
    std::printf("time             cost volume %.1f ms, WTA %.1f ms, confidence %.1f ms\n", ms_cost_volume, ms_wta,
                ms_confidence);
  }
  return 0;
}

}  // namespace

void RegisterStereoEvalCommand(CommandRegistry* registry) {
  registry->Add("stereo-eval", "Evaluate whole-range stereo confidence on a pair with ground truth",
                [](CLI::App& app) -> CommandAction {
                  auto s = std::make_shared<StereoEvalState>();
                  app.add_option("--left", s->left, "Left (reference) image")->required();
                  app.add_option("--right", s->right, "Right image")->required();
                  app.add_option("--gt", s->gt, "Left ground-truth disparity PNG (0 = unknown)")->required();
                  CLI::Option* gt_scale =
                      AddNumberOption(app, "--gt-scale", &s->gt_scale,
                                      "Ground-truth PNG value per pixel of disparity (default: 256 for a 16-bit KITTI "
                                      "file; an 8-bit file needs it)",
                                      NumberRange::AboveAtMost(0.0, 255.0));
                  gt_scale->default_str("");
                  app.add_option("--gt-right", s->gt_right, "Right ground truth, to exclude occluded pixels");
                  CLI::Option* dmax = AddNumberOption(app, "--dmax", &s->dmax,
                                                      "Largest disparity (default: the ground truth's, rounded up "
                                                      "to 16k - 1)",
                                                      NumberRange::Closed(0, kMaxDisparity));
                  dmax->default_str("");
                  AddChoiceOption(app, "--cost", &s->cost, "Window cost", {"ssd", "btsad"});
                  AddNumberOption(app, "--window", &s->window, "Window side (ssd: at most 181)",
                                  NumberRange::Closed(1, 2051).OddOnly());
                  AddChoiceOption(app, "--model", &s->model, "Confidence model", {"matthies", "merrell", "exp", "hsm"});
                  app.add_option("--params", s->params,
                                 "ml (maximum likelihood, no ground truth), gt (fit at true disparities) or a value "
                                 "(greater than 0 and at most " + FormatShort(kMaxParameter) + ")")
                      ->capture_default_str();
                  AddChoiceOption(app, "--prefilter", &s->prefilter, "Prefilter", {"sobel", "none"});
                  AddNumberOption(app, "--border", &s->border, "Ignored border (pixels)",
                                  NumberRange::Closed(0, kMaxBorder));
                  app.add_flag("--json", s->json, "Print one JSON object");
                  return [s, gt_scale, dmax] {
                    s->gt_scale_given = gt_scale->count() > 0;
                    s->dmax_given = dmax->count() > 0;
                    return RunStereoEval(*s);
                  };
                });
}

}  // namespace cairn::cli
