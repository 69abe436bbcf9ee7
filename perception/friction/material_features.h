#pragma once

/// @file
/// Colour and texture features of image patches for the built-in material classifier.

#include <opencv2/core.hpp>

namespace cairn::perception {

/// Per-patch colour and texture descriptors on a regular grid of patch centres.
///
/// For each patch (a `window` x `window` square around a centre, centres every `stride` pixels) the descriptor
/// holds, in this order:
///  - 0..2: mean of CIE L*, a*, b*;
///  - 3..5: standard deviation of L*, a*, b*;
///  - 6, 7: log gradient energy of L* at a fine and a coarse (Gaussian σ = 2) scale;
///  - 8: orientation coherence of the structure tensor (0 isotropic, 1 one direction: brushing, grain, weave);
///  - 9, 10: log band energy |L* − G₁ L*| and |G₁ L* − G₃ L*| (difference of Gaussians);
///  - 11..19: histogram of the rotation-invariant 8-neighbour local binary pattern (how many of the 8 neighbours
///    at radius 1 are brighter than the centre: 0..8).
/// Window statistics are box filters over per-pixel maps, so the cost does not depend on the window size.
class MaterialFeatures {
 public:
  /// Number of values per descriptor.
  static constexpr int kDimension = 20;

  /// Largest patch side and stride, pixels (a model file states both).
  static constexpr int kMaxWindow = 1023;
  /// See kMaxWindow.
  static constexpr int kMaxStride = 1023;

  /// `window`: odd patch side in pixels, in [3, kMaxWindow]; `stride`: distance between patch centres, in
  /// [1, kMaxStride]. Throws std::invalid_argument naming the bad value.
  MaterialFeatures(int window = 15, int stride = 8);

  /// The patch grid of an image: ceil(cols / stride) x ceil(rows / stride) centres.
  cv::Size GridSize(cv::Size image) const;
  /// Pixel column (or row) of grid index i on an axis of `extent` pixels: the centre of the stride cell, clamped.
  int CentreOf(int i, int extent) const;

  /// Descriptors of every patch of an 8-bit BGR (or grey) image: CV_32F, one row per grid cell (row-major over
  /// the grid), kDimension columns. Throws std::invalid_argument for an empty or non-8-bit image, or one narrower
  /// or lower than the window (its patches would be mostly mirrored border).
  cv::Mat Compute(const cv::Mat& image) const;

  int window() const { return window_; }
  int stride() const { return stride_; }

 private:
  int window_;
  int stride_;
};

}  // namespace cairn::perception
