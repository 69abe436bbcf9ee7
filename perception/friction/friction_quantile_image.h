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
/// - kExact: label CDFs tabulated on a 1/2048 grid over [0, max_i q_i], where q_i is label i's own (1−η)
///   quantile: the mixture quantile never exceeds it, since F(max_i q_i) = Σ_i p_i F_i(max_i q_i) >= Σ_i p_i (1−η).
///   The root of the piecewise-linear tabulated CDF is found by Newton steps on the table's cells, safeguarded
///   by bisection, from the probability-weighted mean of the q_i, and is exact inside its cell (linear
///   interpolation); confident pixels need two or three cell evaluations. cdf_interpolation_error() reports the table's largest
///   CDF error (measured at every cell's midpoint).
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
  // 16 floats on a cache line: a table row of up to 16 labels is one line.
  struct alignas(64) Block {
    float values[16]{};
  };
  // Per-thread state of ExactQuantilesOfRow(), one entry per pixel still searching.
  struct Workspace {
    std::vector<int> active, low, high, cell;
  };

  // `padded` holds `cols` pixels of stride_ floats (zeros past num_labels_); `out` receives `cols` quantiles.
  void ExactQuantilesOfRow(const float* padded, int cols, Workspace* workspace, float* out) const;
  void SearchQuantilesOfRow(const float* padded, int cols, float* out) const;
  void GaussianQuantilesOfRow(const float* padded, int cols, float* out) const;
  float* TableRow(int point) { return table_[static_cast<std::size_t>(point) * blocks_].values; }
  const float* TableRow(int point) const { return table_[static_cast<std::size_t>(point) * blocks_].values; }

  Options options_;
  int num_labels_;
  float target_;            // 1 − η
  int blocks_;              // 16-label blocks per pixel
  int stride_;              // 16 * blocks_
  double step_;             // table spacing in μ
  int num_points_;          // table entries per label
  std::vector<Block> table_;  // point j's row: blocks [j * blocks_, (j + 1) * blocks_), F(j * step | label)
  std::vector<float> label_cell_;  // kExact: each label's own quantile in table cells, padded to stride_
  std::vector<float> ones_;  // stride_ ones: pixel sums as dot products
  std::vector<float> mean_, second_moment_;  // kGaussian, padded to stride_
  float z_;                 // Φ⁻¹(1 − η), kGaussian
  double cdf_interpolation_error_{0.0};
};

}  // namespace cairn::perception
