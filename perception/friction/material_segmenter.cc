#include "cairn/common/number_text.h"
#include "cairn/perception/friction/material_segmenter.h"

#include <cmath>
#include <set>
#include <stdexcept>
#include <string>
#include <utility>

namespace cairn::perception {

MaterialSegmenter::MaterialSegmenter(std::vector<std::string> labels) : labels_(std::move(labels)) {
  if (labels_.empty()) throw std::invalid_argument("A material segmenter needs at least one label.");
  std::set<std::string> seen;
  for (const std::string& label : labels_) {
    if (label.empty()) throw std::invalid_argument("A material segmenter label is empty.");
    if (!seen.insert(label).second) {
      throw std::invalid_argument("The material segmenter label '" + label + "' appears twice.");
    }
  }
}

MaterialSegmenter::~MaterialSegmenter() = default;

cv::Mat MaterialSegmenter::Segment(const cv::Mat& image) const {
  if (image.empty()) throw std::invalid_argument("Material segmentation: the image is empty.");
  if (image.depth() != CV_8U || (image.channels() != 1 && image.channels() != 3)) {
    throw std::invalid_argument("Material segmentation needs an 8-bit image with 1 or 3 channels; got depth " +
                                cairn::FormatShort(image.depth()) + " (CV_8U is 0) with " +
                                cairn::FormatShort(image.channels()) + " channel(s). Convert it with cv::Mat::convertTo "
                                "or cv::cvtColor.");
  }
  cv::Mat probabilities = DoSegment(image);
  if (probabilities.rows != image.rows || probabilities.cols != image.cols ||
      probabilities.type() != CV_32FC(num_labels())) {
    throw std::logic_error("The material segmenter returned a " + cairn::FormatShort(probabilities.rows) + "x" +
                           cairn::FormatShort(probabilities.cols) + " image with " +
                           cairn::FormatShort(probabilities.channels()) + " channel(s); expected " +
                           cairn::FormatShort(image.rows) + "x" + cairn::FormatShort(image.cols) + " float with " +
                           cairn::FormatShort(num_labels()) + ".");
  }
  const int n = num_labels();
  for (int r = 0; r < probabilities.rows; ++r) {
    const float* row = probabilities.ptr<float>(r);
    for (int c = 0; c < probabilities.cols; ++c) {
      double sum = 0.0;
      for (int i = 0; i < n; ++i) sum += row[c * n + i];
      if (!(std::abs(sum - 1.0) < 1e-3)) {
        throw std::logic_error("The material segmenter's probabilities at pixel (" + cairn::FormatShort(r) + ", " +
                               cairn::FormatShort(c) + ") sum to " + cairn::FormatShort(sum) + ", not 1.");
      }
    }
  }
  return probabilities;
}

}  // namespace cairn::perception
