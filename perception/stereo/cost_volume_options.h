#pragma once

/// @file
/// How a stereo cost volume is computed: cost function, window, disparity range and prefilter.

#include <string>

namespace cairn::perception {

/// Window cost functions (thesis section 4.3.1).
enum class CostFunction {
  /// Sum of squared intensity differences over the window.
  kSsd,
  /// Sum over the window of Birchfield-Tomasi's sampling-insensitive pixel dissimilarity.
  kBtSad,
};

/// Image prefilters applied to both images before matching.
enum class Prefilter {
  /// Match the grey images as they are.
  kNone,
  /// Horizontal Sobel derivative, clipped to [-cap, cap] and shifted by cap, as OpenCV's block matcher does.
  kSobel,
};

/// Parses "ssd" or "btsad"; throws std::invalid_argument naming the value and the accepted names.
CostFunction ParseCostFunction(const std::string& name);
/// "ssd" or "btsad".
std::string CostFunctionName(CostFunction cost);
/// Parses "sobel" or "none"; throws std::invalid_argument naming the value and the accepted names.
Prefilter ParsePrefilter(const std::string& name);
/// "sobel" or "none".
std::string PrefilterName(Prefilter prefilter);

/// Parameters of ComputeCostVolume(). The defaults are the thesis' configuration: BTSAD on a 9x9 window after a
/// 9x9 Sobel prefilter clipped at 31 (OpenCV's default cap).
struct CostVolumeOptions {
  /// Window cost function.
  CostFunction cost{CostFunction::kBtSad};
  /// Side of the square aggregation window; odd, at least 1.
  int window{9};
  /// Smallest disparity evaluated (pixels; the right-image column is x - d).
  int min_disparity{0};
  /// Largest disparity evaluated; the volume has max_disparity - min_disparity + 1 disparities.
  int max_disparity{63};
  /// Prefilter applied to both images.
  Prefilter prefilter{Prefilter::kSobel};
  /// Aperture of the Sobel prefilter: 3, 5, 7 or 9.
  int prefilter_size{9};
  /// The prefiltered response is clipped to [-prefilter_cap, prefilter_cap]; 1..63 as in OpenCV.
  int prefilter_cap{31};
  /// Worker threads splitting the image rows (0 = one per core; rule: cairn::ResolveThreadCount).
  int num_threads{0};

  /// Checks the options against the image size; throws std::invalid_argument naming the bad value and the fix
  /// (even or non-positive window, a window whose sums would overflow or that is wider or taller than the image,
  /// inverted range, a range wider than the image, bad prefilter settings, negative threads). Pass
  /// kUnknownImageSize for a side not known yet (a matcher checks the options before it sees an image).
  void Validate(int image_width, int image_height) const;

  /// The `image_width`/`image_height` of Validate() that skips the checks against that side.
  static constexpr int kUnknownImageSize = -1;
};

}  // namespace cairn::perception
