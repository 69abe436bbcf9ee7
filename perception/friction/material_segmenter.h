#pragma once

#include <string>
#include <vector>

#include <opencv2/core.hpp>

namespace cairn::perception {

/// Per-pixel material probabilities P(x_k = l_i | image) from an image (thesis 3.5): the interface of every
/// segmentation back-end (a built-in feature classifier, an ONNX network through OpenCV dnn, ...).
///
/// Segment() validates the image, calls DoSegment(), and validates what the back-end returned, so each back-end
/// only computes.
class MaterialSegmenter {
 public:
  virtual ~MaterialSegmenter();

  /// The labels, in the order of the output channels. A FrictionEstimator maps them to its MaterialRegistry.
  const std::vector<std::string>& labels() const { return labels_; }
  int num_labels() const { return static_cast<int>(labels_.size()); }

  /// `image`: 8-bit, 1 channel (grey) or 3 channels (BGR). Returns CV_32FC(num_labels()) of the image's size whose
  /// channels sum to 1 at every pixel. Throws std::invalid_argument naming the bad type, and std::logic_error if the
  /// back-end returns something malformed.
  cv::Mat Segment(const cv::Mat& image) const;

 protected:
  /// Throws std::invalid_argument on an empty or duplicate label.
  explicit MaterialSegmenter(std::vector<std::string> labels);

  /// Computes the probabilities of an already validated image.
  virtual cv::Mat DoSegment(const cv::Mat& image) const = 0;

 private:
  std::vector<std::string> labels_;
};

}  // namespace cairn::perception
