#pragma once

/// @file
/// A per-pixel curve over a disparity range: the stereo cost volume, or a confidence volume computed from it.

#include <cstddef>
#include <cstdint>
#include <vector>

namespace cairn::perception {

/// A dense H x W x D array of floats, one curve of D values per pixel over the disparities
/// [min_disparity, max_disparity]. The D values of a pixel are contiguous (pixel-major layout), because every
/// consumer (winner-take-all, confidence, the occupancy sensor model) walks a whole curve at a time.
///
/// Holds costs (lower is better; +infinity where the disparity points outside the other image) or confidences
/// C(d) (probabilities summing to one over each pixel's curve). Resize() reuses the storage when the shape is
/// unchanged, so one volume can serve as a preallocated workspace across frames.
class DisparityVolume {
 public:
  /// Most values a volume may hold: 2^30 floats, 4 GiB (640x480 over 256 disparities is 79 million).
  static constexpr std::int64_t kMaxValues = std::int64_t{1} << 30;

  /// An empty volume (0 x 0 x 0).
  DisparityVolume() = default;

  /// A volume of `height` x `width` pixels over [min_disparity, max_disparity], filled with zeros.
  /// Throws std::invalid_argument if a size is not positive, max_disparity < min_disparity, or the volume would
  /// hold more than kMaxValues values.
  DisparityVolume(int height, int width, int min_disparity, int max_disparity);

  /// Reshapes the volume; keeps the allocation when the number of elements does not grow. Values are
  /// unspecified afterwards. Same argument checks as the constructor.
  void Resize(int height, int width, int min_disparity, int max_disparity);

  int height() const { return height_; }
  int width() const { return width_; }
  int min_disparity() const { return min_disparity_; }
  int max_disparity() const { return max_disparity_; }
  /// Number of disparities D = max_disparity - min_disparity + 1.
  int num_disparities() const { return num_disparities_; }

  /// The D values of pixel (x, y); element k belongs to disparity min_disparity + k.
  const float* curve(int y, int x) const {
    return data_.data() + (static_cast<std::size_t>(y) * width_ + x) * num_disparities_;
  }
  /// Mutable access to the curve of pixel (x, y).
  float* mutable_curve(int y, int x) {
    return data_.data() + (static_cast<std::size_t>(y) * width_ + x) * num_disparities_;
  }
  /// The value at pixel (x, y) and disparity index k (disparity min_disparity + k).
  float at(int y, int x, int k) const { return curve(y, x)[k]; }

  /// All values, pixel-major (row y, column x, disparity index k).
  const std::vector<float>& data() const { return data_; }

 private:
  int height_{0};
  int width_{0};
  int min_disparity_{0};
  int max_disparity_{-1};
  int num_disparities_{0};
  std::vector<float> data_;
};

}  // namespace cairn::perception
