#pragma once

/// @file
/// Accuracy and calibration of material probabilities against ground-truth label images.

#include <cstdint>
#include <vector>

#include <Eigen/Core>
#include <opencv2/core.hpp>

namespace cairn::perception {

/// Accumulates, over any number of images, how well material probabilities match ground-truth labels: global
/// pixel accuracy, class-average accuracy (mean per-class recall over the classes present, the thesis' SegNet
/// figures are 0.79 and 0.48) and the expected calibration error of the winning probability (reliability of the
/// confidences, 10 equal-width bins).
class MaterialSegmentationScore {
 public:
  /// `num_labels` > 0; throws std::invalid_argument otherwise.
  explicit MaterialSegmentationScore(int num_labels, int num_bins = 10);

  /// Adds one image: `probabilities` CV_32FC(num_labels), `truth` CV_8UC1 of the same size holding label indices
  /// (pixels equal to `ignore`, e.g. 255, are skipped). Throws std::invalid_argument on a size or type mismatch
  /// or a truth value that is neither a label index nor `ignore`.
  void Add(const cv::Mat& probabilities, const cv::Mat& truth, std::uint8_t ignore = 255);

  int num_labels() const { return num_labels_; }
  /// Pixels scored so far.
  std::int64_t num_pixels() const { return num_pixels_; }
  /// Fraction of pixels whose most probable label is the true one (0 before any pixel).
  double pixel_accuracy() const;
  /// Mean over the labels present in the truth of the fraction of their pixels labelled correctly.
  double class_average_accuracy() const;
  /// Σ_bins (n_b / N) |accuracy_b − confidence_b| over bins of the winning probability.
  double expected_calibration_error() const;
  /// Mean negative log-likelihood of the true label (probabilities clamped at 1e-12).
  double mean_negative_log_likelihood() const;
  /// confusion(t, p): pixels of true label t predicted as p.
  const Eigen::Matrix<std::int64_t, Eigen::Dynamic, Eigen::Dynamic>& confusion() const { return confusion_; }

 private:
  int num_labels_;
  int num_bins_;
  std::int64_t num_pixels_{0};
  double sum_nll_{0.0};
  Eigen::Matrix<std::int64_t, Eigen::Dynamic, Eigen::Dynamic> confusion_;
  std::vector<std::int64_t> bin_count_;
  std::vector<std::int64_t> bin_correct_;
  std::vector<double> bin_confidence_;
};

}  // namespace cairn::perception
