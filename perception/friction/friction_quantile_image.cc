#include "cairn/perception/friction/friction_quantile_image.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

#include "cairn/perception/internal/parallel_rows.h"

namespace cairn::perception {
namespace {

constexpr double kExactStep = 1.0 / 2048.0;

std::string Short(double x) {
  char text[32];
  std::snprintf(text, sizeof(text), "%g", x);
  return text;
}

// Σ p[i] row[i] over `blocks` blocks of 16 floats. Eight independent partial sums: without them the additions
// form one dependent chain (the compiler may not reorder float sums), which makes the dot product latency-bound;
// with them it becomes a few vector multiply-adds. The summation order is fixed, so results are reproducible.
inline float Dot(const float* p, const float* row, int blocks) {
  float lanes[8] = {0, 0, 0, 0, 0, 0, 0, 0};
  for (int i = 0; i < 16 * blocks; i += 8) {
    for (int k = 0; k < 8; ++k) lanes[k] += p[i + k] * row[i + k];
  }
  return ((lanes[0] + lanes[4]) + (lanes[1] + lanes[5])) + ((lanes[2] + lanes[6]) + (lanes[3] + lanes[7]));
}

}  // namespace

FrictionQuantileImage::FrictionQuantileImage(const MaterialRegistry& registry, const Options& options)
    : options_(options), num_labels_(registry.size()) {
  if (!(options.eta > 0.0 && options.eta < 1.0)) {
    throw std::invalid_argument("eta (the probability that friction is at least the quantile) must be in (0, 1); "
                                "got " + Short(options.eta) + ".");
  }
  if (!(options.tolerance > 0.0) || !std::isfinite(options.tolerance)) {
    throw std::invalid_argument("The quantile search step must be finite and > 0; got " + Short(options.tolerance) +
                                ".");
  }
  if (num_labels_ == 0) throw std::invalid_argument("FrictionQuantileImage: the material registry is empty.");
  const double target = 1.0 - options.eta;
  target_ = static_cast<float>(target);
  blocks_ = (num_labels_ + 15) / 16;
  stride_ = 16 * blocks_;
  ones_.assign(stride_, 1.0f);

  if (options.method == QuantileMethod::kGaussian) {
    mean_.assign(stride_, 0.0f);
    second_moment_.assign(stride_, 0.0f);
    for (int i = 0; i < num_labels_; ++i) {
      const double m = registry.material(i).friction.Mean();
      mean_[i] = static_cast<float>(m);
      second_moment_[i] = static_cast<float>(registry.material(i).friction.Variance() + m * m);
    }
    z_ = static_cast<float>(StandardNormalQuantile(target));
    step_ = 0.0;
    num_points_ = 0;
    return;
  }

  // The mixture CDF at the largest component quantile is at least the target, so the table can stop there.
  double high = 0.0;
  for (const auto& material : registry.materials()) high = std::max(high, material.friction.Quantile(target));
  step_ = options.method == QuantileMethod::kExact ? kExactStep : options.tolerance;
  num_points_ = static_cast<int>(std::ceil(high / step_)) + 2;
  table_.assign(static_cast<std::size_t>(num_points_) * blocks_, Block{});
  for (int j = 0; j < num_points_; ++j) {
    for (int i = 0; i < num_labels_; ++i) {
      TableRow(j)[i] = static_cast<float>(registry.material(i).friction.Cdf(j * step_));
    }
  }
  if (options.method == QuantileMethod::kExact) {
    label_cell_.assign(stride_, 0.0f);
    for (int i = 0; i < num_labels_; ++i) {
      label_cell_[i] = static_cast<float>(
          std::clamp(registry.material(i).friction.Quantile(target) / step_, 0.0, num_points_ - 1.0));
    }
    for (int j = 0; j + 1 < num_points_; ++j) {
      for (int i = 0; i < num_labels_; ++i) {
        const double interpolated = 0.5 * (TableRow(j)[i] + TableRow(j + 1)[i]);
        // Point masses (not-walkable labels at 0) jump inside the first cell; they are handled exactly by the
        // F(0) >= target test before any interpolation.
        if (j == 0 && !registry.material(i).friction.walkable()) continue;
        cdf_interpolation_error_ = std::max(
            cdf_interpolation_error_, std::abs(interpolated - registry.material(i).friction.Cdf((j + 0.5) * step_)));
      }
    }
  }
}

void FrictionQuantileImage::GaussianQuantilesOfRow(const float* padded, int cols, float* out) const {
  for (int c = 0; c < cols; ++c) {
    const float* p = padded + static_cast<std::size_t>(c) * stride_;
    const float mean = Dot(p, mean_.data(), blocks_);
    const float second = Dot(p, second_moment_.data(), blocks_);
    out[c] = std::max(0.0f, mean + std::sqrt(std::max(second - mean * mean, 0.0f)) * z_);
  }
}

void FrictionQuantileImage::SearchQuantilesOfRow(const float* padded, int cols, float* out) const {
  for (int c = 0; c < cols; ++c) {
    const float* p = padded + static_cast<std::size_t>(c) * stride_;
    // Algorithm 1: the largest grid value whose CDF does not exceed the target.
    float quantile = 0.0f;
    for (int j = 0; j < num_points_; ++j) {
      if (Dot(p, TableRow(j), blocks_) > target_) break;
      quantile = static_cast<float>(j * step_);
    }
    out[c] = quantile;
  }
}

void FrictionQuantileImage::ExactQuantilesOfRow(const float* padded, int cols, Workspace* workspace,
                                                float* out) const {
  // The root of the piecewise-linear tabulated CDF G of each pixel, found in rounds over the pixels still
  // searching ("wavefronts"): a round evaluates G at both ends of one cell per pixel. Pixels are independent, so
  // a round has no dependency chain from one pixel to the next and the processor overlaps them; the per-pixel
  // decisions are selects, not branches, and finished pixels drop out of the compacted list.
  //
  // Per pixel, invariant G(low) < target <= G(high) (point indices; G at the table's last point is only known to
  // reach the target up to rounding). A cell with G(cell) < target <= G(cell + 1) holds the root, which linear
  // interpolation then gives exactly; otherwise the cell's end points move `low` or `high` past the cell, so
  // every pixel finishes. The next cell is Newton's guess with the cell's slope when that stays inside the
  // bracket, else the bracket's middle cell (bisection). The first guess is the probability-weighted mean of
  // the labels' own quantiles: a dot product (no branches), and close for the confident pixels a segmenter
  // mostly produces, whose quantile is near the dominant label's.
  std::vector<int>& active = workspace->active;
  std::vector<int>& low = workspace->low;
  std::vector<int>& high = workspace->high;
  std::vector<int>& cell = workspace->cell;
  const int last = num_points_ - 1;
  int count = 0;
  for (int c = 0; c < cols; ++c) {
    const float* p = padded + static_cast<std::size_t>(c) * stride_;
    out[c] = 0.0f;  // Final for pixels whose mixture reaches the target at μ = 0 (mostly not-walkable ones).
    active[count] = c;
    low[count] = 0;
    high[count] = last;
    cell[count] = std::min(static_cast<int>(Dot(p, label_cell_.data(), blocks_)), last - 1);
    count += Dot(p, TableRow(0), blocks_) < target_ ? 1 : 0;
  }
  while (count > 0) {
    int next = 0;
    for (int k = 0; k < count; ++k) {
      const int c = active[k];
      const float* p = padded + static_cast<std::size_t>(c) * stride_;
      const int j = cell[k];
      const float f_low = Dot(p, TableRow(j), blocks_);
      const float f_high = Dot(p, TableRow(j + 1), blocks_);
      const bool above = f_low >= target_;  // The root is left of the cell.
      const bool below = f_high < target_;  // The root is right of the cell.
      const int new_low = below ? j + 1 : low[k];
      const int new_high = above ? j : high[k];
      // Where the line through the cell's end points meets the target, in cells: the root when the cell holds
      // it, else Newton's next guess; infinite or NaN for a flat cell, which fails the bracket test.
      const float guess = static_cast<float>(j) + (target_ - f_low) / (f_high - f_low);
      const bool inside = guess >= static_cast<float>(new_low) && guess < static_cast<float>(new_high);
      const bool at_end = below && new_low == last;  // Rounding kept G under the target up to the table's end.
      const bool done = !(above || below) || at_end;
      out[c] = static_cast<float>(static_cast<double>(at_end ? static_cast<float>(last) : guess) * step_);
      active[next] = c;
      low[next] = new_low;
      high[next] = new_high;
      cell[next] = std::min(inside ? static_cast<int>(guess) : (new_low + new_high - 1) / 2, last - 1);
      next += done ? 0 : 1;
    }
    count = next;
  }
}

cv::Mat FrictionQuantileImage::Compute(const cv::Mat& probabilities) const {
  cv::Mat quantiles;
  Compute(probabilities, &quantiles);
  return quantiles;
}

void FrictionQuantileImage::Compute(const cv::Mat& probabilities, cv::Mat* quantiles) const {
  if (probabilities.empty() || probabilities.type() != CV_32FC(num_labels_)) {
    throw std::invalid_argument("Friction quantiles need a CV_32FC(" + std::to_string(num_labels_) +
                                ") probability image, one channel per registry label; got type " +
                                std::to_string(probabilities.type()) + " with " +
                                std::to_string(probabilities.channels()) + " channel(s).");
  }
  quantiles->create(probabilities.rows, probabilities.cols, CV_32F);
  const int n = num_labels_;
  const int cols = probabilities.cols;
  std::vector<std::string> errors(internal::ResolveThreadCount(options_.num_threads));
  internal::ParallelForRows(
      probabilities.rows, static_cast<int>(errors.size()), [&](int thread, int row_begin, int row_end) {
        // Each row is copied into pixels of stride_ floats (zeros past the labels), so the dot products with
        // the table run over whole blocks.
        std::vector<float> padded(static_cast<std::size_t>(cols) * stride_, 0.0f);
        Workspace workspace{std::vector<int>(cols), std::vector<int>(cols), std::vector<int>(cols),
                            std::vector<int>(cols)};
        for (int r = row_begin; r < row_end; ++r) {
          const float* row = probabilities.ptr<float>(r);
          float* out = quantiles->ptr<float>(r);
          // Pixels padded to stride_ floats. A pixel's copy may read stride_ floats when the row holds that many
          // from its start (the excess, the next pixel's values, is zeroed): a fixed-length copy, not a call.
          for (int c = 0; c < cols; ++c) {
            const float* p = row + static_cast<std::size_t>(c) * n;
            float* q = padded.data() + static_cast<std::size_t>(c) * stride_;
            if (static_cast<long>(cols - c) * n >= stride_) {
              for (int i = 0; i < stride_; ++i) q[i] = p[i];
              for (int i = n; i < stride_; ++i) q[i] = 0.0f;
            } else {
              std::copy_n(p, n, q);
            }
          }
          // Validation as separate passes, bitwise and branch-free so they vectorise: the range over the row's
          // values, then each pixel's sum. NaN passes the range test but not the sum's.
          int outside = 0;
          for (int i = 0; i < cols * n; ++i) outside |= (row[i] < 0.0f) | (row[i] > 1.0f);
          bool row_valid = outside == 0;
          for (int c = 0; c < cols; ++c) {
            const float sum = Dot(padded.data() + static_cast<std::size_t>(c) * stride_, ones_.data(), blocks_);
            row_valid &= std::abs(sum - 1.0f) <= 1e-3f;
          }
          if (!row_valid) {
            for (int c = 0; c < cols; ++c) {
              const float* p = row + static_cast<std::size_t>(c) * n;
              float sum = 0.0f;
              bool in_range = true;
              for (int i = 0; i < n; ++i) {
                sum += p[i];
                in_range = in_range && p[i] >= 0.0f && p[i] <= 1.0f;
              }
              if (in_range && std::abs(sum - 1.0f) <= 1e-3f) continue;
              errors[thread] = "The material probabilities at pixel (" + std::to_string(r) + ", " +
                               std::to_string(c) + ") " +
                               (in_range ? "sum to " + Short(sum) + ", not 1" : std::string("leave [0, 1]")) +
                               "; normalise them (e.g. with a softmax).";
              return;
            }
          }
          switch (options_.method) {
            case QuantileMethod::kExact:
              ExactQuantilesOfRow(padded.data(), cols, &workspace, out);
              break;
            case QuantileMethod::kSearch:
              SearchQuantilesOfRow(padded.data(), cols, out);
              break;
            case QuantileMethod::kGaussian:
              GaussianQuantilesOfRow(padded.data(), cols, out);
              break;
          }
        }
      });
  for (const std::string& error : errors) {
    if (!error.empty()) throw std::invalid_argument(error);
  }
}

}  // namespace cairn::perception
