#include "cairn/common/number_text.h"
#include "cairn/perception/stereo/cost_samples.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include "cairn/common/cairn_assert.h"

namespace cairn::perception {

std::size_t CollectConsistentWtaCosts(const DisparityVolume& costs, const WtaResult& wta, std::vector<float>* samples) {
  CAIRN_CHECK(samples != nullptr);
  if (wta.best_cost.rows != costs.height() || wta.best_cost.cols != costs.width() ||
      wta.best_cost.type() != CV_32FC1 || wta.lr_consistent.size() != wta.best_cost.size() ||
      wta.lr_consistent.type() != CV_8UC1) {
    throw std::invalid_argument("CollectConsistentWtaCosts: the winner-take-all result is " +
                                cairn::FormatShort(wta.best_cost.cols) + "x" + cairn::FormatShort(wta.best_cost.rows) +
                                " but the cost volume is " + cairn::FormatShort(costs.width()) + "x" +
                                cairn::FormatShort(costs.height()) +
                                " (or lacks its cost or left-right matrices); compute both from the same pair");
  }
  const std::size_t before = samples->size();
  for (int y = 0; y < costs.height(); ++y) {
    const float* best = wta.best_cost.ptr<float>(y);
    const uint8_t* ok = wta.lr_consistent.ptr<uint8_t>(y);
    for (int x = 0; x < costs.width(); ++x) {
      if (ok[x] != 0 && std::isfinite(best[x])) samples->push_back(best[x]);
    }
  }
  return samples->size() - before;
}

std::size_t CollectGroundTruthCosts(const DisparityVolume& costs, const cv::Mat& ground_truth, const cv::Mat& mask,
                                    std::vector<float>* samples) {
  CAIRN_CHECK(samples != nullptr);
  if (ground_truth.type() != CV_32FC1 || ground_truth.rows != costs.height() || ground_truth.cols != costs.width()) {
    throw std::invalid_argument("CollectGroundTruthCosts: ground truth must be CV_32FC1 of the volume's size " +
                                cairn::FormatShort(costs.width()) + "x" + cairn::FormatShort(costs.height()) + ", got " +
                                cairn::FormatShort(ground_truth.cols) + "x" + cairn::FormatShort(ground_truth.rows) +
                                " of type " + cairn::FormatShort(ground_truth.type()) +
                                "; load it with LoadDisparityImage()");
  }
  if (!mask.empty() && (mask.type() != CV_8UC1 || mask.size() != ground_truth.size())) {
    throw std::invalid_argument("CollectGroundTruthCosts: the mask must be CV_8UC1 of the ground truth's size");
  }
  const std::size_t before = samples->size();
  for (int y = 0; y < costs.height(); ++y) {
    const float* gt = ground_truth.ptr<float>(y);
    for (int x = 0; x < costs.width(); ++x) {
      if (!(gt[x] > 0.0f) || !std::isfinite(gt[x]) || (!mask.empty() && mask.at<uint8_t>(y, x) == 0)) continue;
      const int k = static_cast<int>(std::lround(gt[x])) - costs.min_disparity();
      if (k < 0 || k >= costs.num_disparities()) continue;
      const float value = costs.at(y, x, k);
      if (std::isfinite(value)) samples->push_back(value);
    }
  }
  return samples->size() - before;
}

}  // namespace cairn::perception
