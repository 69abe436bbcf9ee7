#pragma once

#include <string>
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
///   by bisection, from where the labels' CDFs linearised at their q_i meet the target, and is exact inside its
///   cell (linear interpolation); confident pixels need two or three cell evaluations. cdf_interpolation_error()
///   reports the table's largest CDF error (measured at every cell's midpoint).
/// - kSearch: the thesis' Algorithm 1 with step `tolerance`, on CDFs tabulated at its grid points (exact values).
/// - kGaussian: the moment approximation.
/// Rows are split across threads. Each row is read in one pass that validates it and takes each pixel's sum and
/// the dot products the method starts from; the searches then revisit only their pixels' table cells. The dot
/// products run on AVX2 when the processor has it, reading the row where it lies, else on portable code that copies
/// the row into padded pixels and adds in the same order, so results depend neither on the thread count nor on the
/// processor.
class FrictionQuantileImage {
 public:
  struct Options {
    double eta{0.95};
    QuantileMethod method{QuantileMethod::kExact};
    /// Step of kSearch (the thesis used 0.02); unused by the other methods.
    double tolerance{0.02};
    /// Threads (0 = one per core; rule: cairn::ResolveThreadCount).
    int num_threads{0};
  };

  /// Most points a CDF table may have (per label: kExact and kSearch tabulate every label's CDF from 0 to the
  /// largest label quantile; a million points of 16 labels take 64 MB).
  static constexpr double kMaxTablePoints = 1e6;

  /// Throws std::invalid_argument for η outside (0, 1), a non-positive tolerance, an empty registry, or a table of
  /// more than kMaxTablePoints points (a tiny tolerance, or a label quantile of implausible friction).
  FrictionQuantileImage(const MaterialRegistry& registry, const Options& options);

  /// `probabilities`: CV_32FC(number of labels), channels in registry order, each pixel's summing to 1.
  /// Returns CV_32F quantiles of the same size. Throws std::invalid_argument naming the first bad pixel.
  cv::Mat Compute(const cv::Mat& probabilities) const;
  /// As Compute(), into `quantiles` (reallocated only when its size or type differs, or when it shares the
  /// probabilities' pixels; `quantiles` may be `&probabilities`).
  void Compute(const cv::Mat& probabilities, cv::Mat* quantiles) const;

  const Options& options() const { return options_; }
  int num_labels() const { return num_labels_; }
  /// Largest |tabulated − exact| mixture CDF of kExact's table (0 for the other methods).
  double cdf_interpolation_error() const { return cdf_interpolation_error_; }

 private:
  // Tests switch an image to the portable kernels to compare them with the AVX2 ones.
  friend class FrictionQuantileImageTester;

  // 16 floats on a cache line: a table row of up to 16 labels (zeros past num_labels_) is one line.
  struct alignas(64) Block {
    float values[16]{};
  };
  // Per-thread arrays of one row's pixels (defined in the source file).
  struct Workspace;

  // Each reads a validated row of `cols` pixels (num_labels_ floats each) and the workspace's results of the
  // validation pass (see dot_vectors_), and writes `cols` quantiles to `out`.
  void ExactQuantilesOfRow(const float* row, int cols, Workspace* workspace, float* out) const;
  void SearchQuantilesOfRow(const float* row, int cols, Workspace* workspace, float* out) const;
  void GaussianQuantilesOfRow(int cols, const Workspace& workspace, float* out) const;
  // The error message naming the first pixel of row `r` whose probabilities leave [0, 1] or do not sum to 1.
  std::string DescribeFirstBadPixel(const float* row, int r, int cols) const;
  float* TableRow(int point) { return table_[static_cast<std::size_t>(point) * blocks_].values; }
  const float* TableRow(int point) const { return table_[static_cast<std::size_t>(point) * blocks_].values; }
  float* DotVector(int k) { return dot_vectors_[static_cast<std::size_t>(k) * blocks_].values; }
  const float* DotVector(int k) const { return dot_vectors_[static_cast<std::size_t>(k) * blocks_].values; }

  Options options_;
  int num_labels_;
  float target_;            // 1 − η
  int blocks_;              // 16-label blocks per table row
  int stride_;              // 16 * blocks_
  double step_;             // table spacing in μ
  int num_points_;          // table entries per label
  std::vector<Block> table_;  // point j's row: blocks [j * blocks_, (j + 1) * blocks_), F(j * step | label)
  // The validation pass dots every pixel with these rows: ones (the pixel's sum), then per method
  // kExact: the numerator and the denominator of the first guess (see the constructor), and F(0 | label);
  // kSearch: F(0 | label) and F(step | label) (Algorithm 1's first two grid points);
  // kGaussian: each label's mean and second moment.
  int num_dot_vectors_;
  std::vector<Block> dot_vectors_;
  float z_{0.0f};           // Φ⁻¹(1 − η), kGaussian
  double cdf_interpolation_error_{0.0};
  bool avx2_{false};        // The dot products run on AVX2 (else on the portable kernels, same results).
};

}  // namespace cairn::perception
