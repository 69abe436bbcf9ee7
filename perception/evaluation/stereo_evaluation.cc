#include "cairn/common/number_text.h"
#include "cairn/perception/evaluation/stereo_evaluation.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <stdexcept>
#include <string>

#include "cairn/common/number_text.h"

namespace cairn::perception {

void StereoEvaluationOptions::Validate(int width, int height) const {
  if (border < 0) {
    throw std::invalid_argument("stereo evaluation border " + cairn::FormatShort(border) +
                                " is negative; give the number of pixels to ignore along each edge (e.g. 10)");
  }
  const int smaller = std::min(width, height);
  if (static_cast<std::int64_t>(border) * 2 >= smaller) {
    throw std::invalid_argument("stereo evaluation border " + cairn::FormatShort(border) + " leaves no pixel of the " +
                                cairn::FormatShort(width) + "x" + cairn::FormatShort(height) + " image; use at most " +
                                cairn::FormatShort(std::max(0, (smaller - 1) / 2)));
  }
  if (!(bad_threshold >= 0.0) || !std::isfinite(bad_threshold)) {
    throw std::invalid_argument("stereo evaluation bad_threshold " + FormatShort(bad_threshold) +
                                " must be finite and >= 0 pixels (the thesis uses 1)");
  }
  if (!(gt_interval >= 0.0) || !std::isfinite(gt_interval)) {
    throw std::invalid_argument("stereo evaluation gt_interval " + FormatShort(gt_interval) +
                                " must be finite and >= 0 pixels (the thesis uses 1)");
  }
}

double RocAuc(const std::vector<float>& confidence, const std::vector<uint8_t>& is_error) {
  if (confidence.size() != is_error.size() || confidence.empty()) {
    throw std::invalid_argument("RocAuc: got " + cairn::FormatShort(confidence.size()) + " confidences and " +
                                cairn::FormatShort(is_error.size()) + " error flags; pass one flag per pixel, at least one");
  }
  // NaN breaks the strict weak order the sort needs (undefined behaviour, not merely a wrong curve).
  const auto nan = std::find_if(confidence.begin(), confidence.end(), [](float c) { return std::isnan(c); });
  if (nan != confidence.end()) {
    throw std::invalid_argument("RocAuc: confidence " + cairn::FormatShort(nan - confidence.begin()) +
                                " is NaN; confidences must be numbers to be ranked");
  }
  std::vector<std::size_t> order(confidence.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return confidence[a] > confidence[b]; });
  const double n = static_cast<double>(order.size());
  double area = 0.0;
  double previous_p = 0.0;
  double previous_rate = -1.0;
  std::size_t taken = 0;
  std::size_t errors = 0;
  std::size_t i = 0;
  while (i < order.size()) {
    const float value = confidence[order[i]];
    while (i < order.size() && confidence[order[i]] == value) {
      errors += is_error[order[i]] != 0 ? 1 : 0;
      ++taken;
      ++i;
    }
    const double p = static_cast<double>(taken) / n;
    const double rate = static_cast<double>(errors) / static_cast<double>(taken);
    if (previous_rate < 0.0) previous_rate = rate;  // The curve starts at the first group's error rate.
    area += 0.5 * (previous_rate + rate) * (p - previous_p);
    previous_p = p;
    previous_rate = rate;
  }
  return area;
}

double OptimalAuc(double error_rate) {
  if (!(error_rate >= 0.0 && error_rate <= 1.0)) {
    throw std::invalid_argument("OptimalAuc: error rate " + cairn::FormatShort(error_rate) + " is outside [0, 1]");
  }
  if (error_rate >= 1.0) return 1.0;
  return error_rate + (1.0 - error_rate) * std::log1p(-error_rate);
}

int AutomaticMaxDisparity(const cv::Mat& ground_truth) {
  if (ground_truth.empty() || ground_truth.type() != CV_32FC1) {
    throw std::invalid_argument("AutomaticMaxDisparity: the ground truth must be a non-empty CV_32FC1 image "
                                "(LoadDisparityImage)");
  }
  if (cv::checkRange(ground_truth) == false) {
    throw std::invalid_argument("AutomaticMaxDisparity: the ground truth holds a non-finite value");
  }
  double max_gt = 0.0;
  cv::minMaxLoc(ground_truth, nullptr, &max_gt);
  if (!(max_gt > 0.0)) {
    throw std::invalid_argument("AutomaticMaxDisparity: the ground truth has no known (positive) disparity; give "
                                "the largest disparity explicitly");
  }
  if (max_gt >= ground_truth.cols) {
    throw std::invalid_argument("AutomaticMaxDisparity: the ground truth's largest disparity " + FormatShort(max_gt) +
                                " px is not below its width " + cairn::FormatShort(ground_truth.cols) +
                                " px; check its scale");
  }
  const int rounded = 16 * (static_cast<int>(std::floor(max_gt)) / 16 + 1) - 1;
  return std::min(rounded, ground_truth.cols - 1);
}

StereoEvaluation EvaluateStereo(const DisparityVolume& confidence, const WtaResult& wta, const cv::Mat& ground_truth,
                                const cv::Mat& occluded, const StereoEvaluationOptions& options) {
  const int height = confidence.height();
  const int width = confidence.width();
  if (confidence.num_disparities() == 0) {
    throw std::invalid_argument("EvaluateStereo: the confidence volume is empty; run ComputeConfidence() first");
  }
  if (ground_truth.type() != CV_32FC1 || ground_truth.rows != height || ground_truth.cols != width) {
    throw std::invalid_argument("EvaluateStereo: the ground truth is " + cairn::FormatShort(ground_truth.cols) + "x" +
                                cairn::FormatShort(ground_truth.rows) + " (type " + cairn::FormatShort(ground_truth.type()) +
                                ") but the images are " + cairn::FormatShort(width) + "x" + cairn::FormatShort(height) +
                                "; pass the left view's ground truth as CV_32FC1 (LoadDisparityImage)");
  }
  if (wta.disparity.rows != height || wta.disparity.cols != width || wta.disparity.type() != CV_32FC1 ||
      wta.best_index.size() != wta.disparity.size() || wta.best_index.type() != CV_32SC1) {
    throw std::invalid_argument("EvaluateStereo: the winner-take-all result does not match the confidence volume's "
                                "size (or is not a ComputeWinnerTakeAll() result); compute both from the same cost "
                                "volume");
  }
  if (!occluded.empty() && (occluded.type() != CV_8UC1 || occluded.size() != ground_truth.size())) {
    throw std::invalid_argument("EvaluateStereo: the occlusion mask must be CV_8UC1 of the ground truth's size");
  }
  options.Validate(width, height);
  const int dmin = confidence.min_disparity();
  const int dmax = confidence.max_disparity();
  std::vector<float> wta_confidence;
  std::vector<uint8_t> bad;
  double c_gt_sum = 0.0;
  std::size_t bad_subpixel = 0;
  for (int y = options.border; y < height - options.border; ++y) {
    const float* gt = ground_truth.ptr<float>(y);
    const float* disparity = wta.disparity.ptr<float>(y);
    const int32_t* best = wta.best_index.ptr<int32_t>(y);
    for (int x = options.border; x < width - options.border; ++x) {
      const float truth = gt[x];
      if (best[x] >= confidence.num_disparities()) {
        throw std::invalid_argument("EvaluateStereo: the winner-take-all index " + cairn::FormatShort(best[x]) +
                                    " at pixel (" + cairn::FormatShort(x) + ", " + cairn::FormatShort(y) +
                                    ") is outside the volume's " + cairn::FormatShort(confidence.num_disparities()) +
                                    " disparities; compute both from the same cost volume");
      }
      if (!(truth > 0.0f) || !std::isfinite(truth) || best[x] < 0) continue;
      if (!occluded.empty() && occluded.at<uint8_t>(y, x) != 0) continue;
      if (truth < static_cast<float>(dmin) || truth > static_cast<float>(dmax) || x - truth < 0.0f) continue;
      const float* c = confidence.curve(y, x);
      const bool is_bad = std::abs(static_cast<float>(dmin + best[x]) - truth) > options.bad_threshold;
      if (std::abs(disparity[x] - truth) > options.bad_threshold) ++bad_subpixel;
      wta_confidence.push_back(c[best[x]]);
      bad.push_back(is_bad ? 1 : 0);
      if (is_bad) {
        // Clamped in double: a wide interval must not overflow the conversion.
        const int lo = static_cast<int>(std::max<double>(dmin, std::ceil(truth - options.gt_interval)));
        const int hi = static_cast<int>(std::min<double>(dmax, std::floor(truth + options.gt_interval)));
        double mass = 0.0;
        for (int d = lo; d <= hi; ++d) mass += c[d - dmin];
        c_gt_sum += mass;
      }
    }
  }
  if (wta_confidence.empty()) {
    throw std::invalid_argument("EvaluateStereo: no pixel could be evaluated; check the ground-truth scale, the "
                                "disparity range (it must cover the true disparities) and the border");
  }
  StereoEvaluation result;
  result.num_pixels = wta_confidence.size();
  result.num_bad = static_cast<std::size_t>(std::count(bad.begin(), bad.end(), 1));
  result.bad_pixel_rate = static_cast<double>(result.num_bad) / static_cast<double>(result.num_pixels);
  result.bad_pixel_rate_subpixel = static_cast<double>(bad_subpixel) / static_cast<double>(result.num_pixels);
  result.auc = RocAuc(wta_confidence, bad);
  result.auc_optimal = OptimalAuc(result.bad_pixel_rate);
  result.c_gt_badpx = result.num_bad > 0 ? c_gt_sum / static_cast<double>(result.num_bad) : 0.0;
  return result;
}

}  // namespace cairn::perception
