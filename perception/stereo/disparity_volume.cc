#include "cairn/common/number_text.h"
#include "cairn/perception/stereo/disparity_volume.h"

#include <algorithm>
#include <cstdint>
#include <stdexcept>
#include <string>

namespace cairn::perception {

DisparityVolume::DisparityVolume(int height, int width, int min_disparity, int max_disparity) {
  Resize(height, width, min_disparity, max_disparity);
  std::fill(data_.begin(), data_.end(), 0.0f);
}

void DisparityVolume::Resize(int height, int width, int min_disparity, int max_disparity) {
  if (height <= 0 || width <= 0) {
    throw std::invalid_argument("DisparityVolume: the image size must be positive, got " + cairn::FormatShort(width) +
                                "x" + cairn::FormatShort(height) + "; pass the size of the rectified images");
  }
  if (max_disparity < min_disparity) {
    throw std::invalid_argument("DisparityVolume: max_disparity " + cairn::FormatShort(max_disparity) +
                                " is below min_disparity " + cairn::FormatShort(min_disparity) +
                                "; swap them or widen the range");
  }
  // In 64 bits: the range of two ints, and the element count, overflow int.
  const std::int64_t disparities = static_cast<std::int64_t>(max_disparity) - min_disparity + 1;
  const std::int64_t values = static_cast<std::int64_t>(height) * width * disparities;
  if (values > kMaxValues) {
    throw std::invalid_argument("DisparityVolume: " + cairn::FormatShort(width) + "x" + cairn::FormatShort(height) +
                                " pixels x " + cairn::FormatShort(disparities) + " disparities are " +
                                cairn::FormatShort(values) + " values, more than the " + cairn::FormatShort(kMaxValues) +
                                " (4 GiB) a volume may hold; narrow the disparity range or downscale the images");
  }
  height_ = height;
  width_ = width;
  min_disparity_ = min_disparity;
  max_disparity_ = max_disparity;
  num_disparities_ = max_disparity - min_disparity + 1;
  data_.resize(static_cast<std::size_t>(height) * width * num_disparities_);
}

}  // namespace cairn::perception
