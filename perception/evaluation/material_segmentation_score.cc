#include "cairn/perception/evaluation/material_segmentation_score.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace cairn::perception {

MaterialSegmentationScore::MaterialSegmentationScore(int num_labels, int num_bins)
    : num_labels_(num_labels), num_bins_(num_bins) {
  if (num_labels < 1) {
    throw std::invalid_argument("MaterialSegmentationScore: num_labels must be >= 1; got " +
                                std::to_string(num_labels) + ".");
  }
  if (num_bins < 1) {
    throw std::invalid_argument("MaterialSegmentationScore: num_bins must be >= 1; got " + std::to_string(num_bins) +
                                ". Use 10.");
  }
  confusion_.setZero(num_labels, num_labels);
  bin_count_.assign(static_cast<std::size_t>(num_bins), 0);
  bin_correct_.assign(static_cast<std::size_t>(num_bins), 0);
  bin_confidence_.assign(static_cast<std::size_t>(num_bins), 0.0);
}

void MaterialSegmentationScore::Add(const cv::Mat& probabilities, const cv::Mat& truth, std::uint8_t ignore) {
  if (probabilities.type() != CV_32FC(num_labels_)) {
    throw std::invalid_argument("MaterialSegmentationScore: probabilities must be CV_32FC(" +
                                std::to_string(num_labels_) + "); got " + std::to_string(probabilities.channels()) +
                                " channel(s) of depth " + std::to_string(probabilities.depth()) + ".");
  }
  if (truth.type() != CV_8UC1 || truth.size() != probabilities.size()) {
    throw std::invalid_argument("MaterialSegmentationScore: the truth must be CV_8UC1 of the probabilities' size " +
                                std::to_string(probabilities.cols) + "x" + std::to_string(probabilities.rows) +
                                "; got " + std::to_string(truth.cols) + "x" + std::to_string(truth.rows) +
                                " of type " + std::to_string(truth.type()) + ".");
  }
  const int n = num_labels_;
  for (int r = 0; r < truth.rows; ++r) {
    const float* p = probabilities.ptr<float>(r);
    const std::uint8_t* t = truth.ptr<std::uint8_t>(r);
    for (int c = 0; c < truth.cols; ++c) {
      if (t[c] == ignore) continue;
      if (t[c] >= n) {
        throw std::invalid_argument("MaterialSegmentationScore: truth pixel (" + std::to_string(r) + ", " +
                                    std::to_string(c) + ") holds " + std::to_string(t[c]) + ", not a label index " +
                                    "below " + std::to_string(n) + " nor the ignore value " +
                                    std::to_string(ignore) + ".");
      }
      const float* q = p + c * n;
      const int predicted = static_cast<int>(std::max_element(q, q + n) - q);
      const double confidence = q[predicted];
      ++confusion_(t[c], predicted);
      ++num_pixels_;
      sum_nll_ -= std::log(std::max(static_cast<double>(q[t[c]]), 1e-12));
      const int bin = std::clamp(static_cast<int>(confidence * num_bins_), 0, num_bins_ - 1);
      ++bin_count_[static_cast<std::size_t>(bin)];
      bin_correct_[static_cast<std::size_t>(bin)] += predicted == t[c] ? 1 : 0;
      bin_confidence_[static_cast<std::size_t>(bin)] += confidence;
    }
  }
}

double MaterialSegmentationScore::pixel_accuracy() const {
  if (num_pixels_ == 0) return 0.0;
  return static_cast<double>(confusion_.diagonal().sum()) / static_cast<double>(num_pixels_);
}

double MaterialSegmentationScore::class_average_accuracy() const {
  double sum = 0.0;
  int present = 0;
  for (int t = 0; t < num_labels_; ++t) {
    const std::int64_t total = confusion_.row(t).sum();
    if (total == 0) continue;
    sum += static_cast<double>(confusion_(t, t)) / static_cast<double>(total);
    ++present;
  }
  return present == 0 ? 0.0 : sum / present;
}

double MaterialSegmentationScore::expected_calibration_error() const {
  if (num_pixels_ == 0) return 0.0;
  double ece = 0.0;
  for (std::size_t b = 0; b < bin_count_.size(); ++b) {
    if (bin_count_[b] == 0) continue;
    const double n = static_cast<double>(bin_count_[b]);
    ece += n / static_cast<double>(num_pixels_) *
           std::abs(static_cast<double>(bin_correct_[b]) / n - bin_confidence_[b] / n);
  }
  return ece;
}

double MaterialSegmentationScore::mean_negative_log_likelihood() const {
  return num_pixels_ == 0 ? 0.0 : sum_nll_ / static_cast<double>(num_pixels_);
}

}  // namespace cairn::perception
