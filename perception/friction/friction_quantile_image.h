#pragma once

#include <vector>

#include <opencv2/core.hpp>

#include "cairn/perception/friction/friction_quantile.h"
#include "cairn/perception/friction/material_registry.h"

namespace cairn::perception {

/// Friction quantile images Q_{1−η} (thesis eq. 5.3) for per-pixel material probabilities, at frame rate: the
/// labels' CDFs are tabulated once, so a pixel costs a short search over a table instead of many CDF evaluations.
///
/// Methods, as FrictionQuantile():
/// - kExact: label CDFs tabulated on a 1/2048 grid over [0, max_i q_i] (the mixture quantile never exceeds the
///   largest component quantile), binary search for the bracketing cell, linear interpolation inside it.
///   cdf_interpolation_error() reports the table's largest CDF error (measured at every cell's midpoint).
/// - kSearch: the thesis' Algorithm 1 with step `tolerance`, on CDFs tabulated at its grid points (exact values).
/// - kGaussian: the moment approximation.
/// Rows are split across threads; results do not depend on the thread count.
class FrictionQuantileImage {
 public:
  struct Options {
    double eta{0.95};
    QuantileMethod method{QuantileMethod::kExact};
    /// Step of kSearch (the thesis used 0.02); unused by the other methods.
    double tolerance{0.02};
    /// 0 = one per core.
    int num_threads{0};
  };

  /// Throws std::invalid_argument for η outside (0, 1), a non-positive tolerance, or an empty registry.
  FrictionQuantileImage(const MaterialRegistry& registry, const Options& options);

  /// `probabilities`: CV_32FC(number of labels), channels in registry order, each pixel's summing to 1.
  /// Returns CV_32F quantiles of the same size. Throws std::invalid_argument naming the first bad pixel.
  cv::Mat Compute(const cv::Mat& probabilities) const;
  /// As Compute(), into `quantiles` (reallocated only when its size or type differs).
  void Compute(const cv::Mat& probabilities, cv::Mat* quantiles) const;

  const Options& options() const { return options_; }
  int num_labels() const { return num_labels_; }
  /// Largest |tabulated − exact| mixture CDF of kExact's table (0 for the other methods).
  double cdf_interpolation_error() const { return cdf_interpolation_error_; }

 private:
  // `p` is padded to stride_ entries (zeros past num_labels_).
  float QuantileOfPixel(const float* p) const;
  float CdfAt(int point, const float* p) const;

  Options options_;
  int num_labels_;
  float target_;            // 1 − η
  double step_;             // table spacing in μ
  int num_points_;          // table entries per label
  int stride_;              // labels padded to a multiple of 8 so the per-point dot product vectorises
  std::vector<float> table_;  // [point * stride + label] = F(point * step | label), zero padding
  std::vector<float> mean_, second_moment_;  // kGaussian
  float z_;                 // Φ⁻¹(1 − η), kGaussian
  double cdf_interpolation_error_{0.0};
};

}  // namespace cairn::perception
