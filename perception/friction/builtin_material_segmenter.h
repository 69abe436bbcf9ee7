#pragma once

/// @file
/// A material segmenter that needs no downloaded weights: patch features and a small calibrated classifier.

#include <cstdint>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <opencv2/core.hpp>

#include "cairn/perception/friction/material_features.h"
#include "cairn/perception/friction/material_segmenter.h"

namespace cairn::perception {

/// Per-patch MaterialFeatures classified by a one-hidden-layer perceptron (ReLU, softmax output) trained in-process
/// on labelled images, with probabilities calibrated by temperature scaling on held-out images and bilinearly
/// upsampled from the patch grid to pixels (a convex combination, so they still sum to 1).
///
/// Immutable once trained or loaded; Segment() may be called from several threads.
class BuiltinMaterialSegmenter final : public MaterialSegmenter {
 public:
  /// How Train() works.
  struct TrainingOptions {
    /// Patch side and patch-grid stride in pixels (see MaterialFeatures).
    int window{15};
    int stride{8};
    /// Hidden units of the perceptron; in [1, kMaxHiddenUnits].
    int hidden_units{48};
    /// Passes over the training samples; >= 1.
    int epochs{40};
    /// Adam step size; > 0.
    double learning_rate{3e-3};
    /// L2 penalty on the weights; >= 0.
    double weight_decay{1e-4};
    /// Fraction of the images (the last ones) held out to fit the temperature; in (0, 1).
    double calibration_fraction{0.25};
    /// Training patches kept per label (a deterministic subsample), to bound time and balance labels; >= 1.
    int max_samples_per_label{3000};
    /// Seeds weight initialisation, subsampling and the mini-batch order.
    std::uint32_t seed{1};
  };

  /// What Train() measured.
  struct TrainingReport {
    int num_training_samples{0};
    int num_calibration_samples{0};
    /// Patch accuracy on the training samples.
    double training_accuracy{0.0};
    /// Patch accuracy on the calibration samples.
    double calibration_accuracy{0.0};
    /// The fitted temperature (probabilities are softmax(logits / temperature)).
    double temperature{1.0};
    /// Expected calibration error and mean negative log-likelihood on the calibration patches, before (T = 1)
    /// and after temperature scaling.
    double ece_before{0.0};
    double ece_after{0.0};
    double nll_before{0.0};
    double nll_after{0.0};
  };

  /// Most hidden units a model may have (trained or read from a file).
  static constexpr int kMaxHiddenUnits = 4096;

  /// Trains on `images` (8-bit BGR or grey, each at least window x window pixels) with `label_images` (CV_8UC1 of
  /// the same sizes, values = indices into `labels`, 255 = unlabelled). Needs at least 2 images (the last ones
  /// calibrate). Throws std::invalid_argument naming the bad image, pixel or option.
  static BuiltinMaterialSegmenter Train(const std::vector<std::string>& labels, const std::vector<cv::Mat>& images,
                                        const std::vector<cv::Mat>& label_images, const TrainingOptions& options,
                                        TrainingReport* report = nullptr);

  /// Reads a model written by Save(); throws std::invalid_argument naming the file, the line and what is wrong
  /// with it (including a window, stride or hidden-unit count beyond the limits above, or more than 255 labels)
  /// and how to re-create it.
  static BuiltinMaterialSegmenter Load(const std::string& path);
  /// Writes the model as YAML, atomically. Throws std::runtime_error naming the path on failure.
  void Save(const std::string& path) const;

  /// Calibrated probabilities on the patch grid: CV_32FC(num_labels()) of features().GridSize(image.size()).
  cv::Mat SegmentGrid(const cv::Mat& image) const;

  const MaterialFeatures& features() const { return features_; }
  double temperature() const { return temperature_; }
  int hidden_units() const { return static_cast<int>(b1_.size()); }

 protected:
  cv::Mat DoSegment(const cv::Mat& image) const override;

 private:
  BuiltinMaterialSegmenter(std::vector<std::string> labels, MaterialFeatures features, Eigen::VectorXf mean,
                           Eigen::VectorXf inverse_scale, Eigen::MatrixXf w1, Eigen::VectorXf b1, Eigen::MatrixXf w2,
                           Eigen::VectorXf b2, double temperature);

  MaterialFeatures features_;
  // Feature standardisation: (x - mean_) .* inverse_scale_.
  Eigen::VectorXf mean_;
  Eigen::VectorXf inverse_scale_;
  // hidden = relu(w1_ x + b1_); logits = w2_ hidden + b2_.
  Eigen::MatrixXf w1_;
  Eigen::VectorXf b1_;
  Eigen::MatrixXf w2_;
  Eigen::VectorXf b2_;
  double temperature_;
};

}  // namespace cairn::perception
