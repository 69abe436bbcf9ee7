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

  if (options.method == QuantileMethod::kGaussian) {
    for (const auto& material : registry.materials()) {
      const double m = material.friction.Mean();
      mean_.push_back(static_cast<float>(m));
      second_moment_.push_back(static_cast<float>(material.friction.Variance() + m * m));
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
  stride_ = (num_labels_ + 7) / 8 * 8;
  table_.assign(static_cast<std::size_t>(num_points_) * stride_, 0.0f);
  for (int j = 0; j < num_points_; ++j) {
    for (int i = 0; i < num_labels_; ++i) {
      table_[static_cast<std::size_t>(j) * stride_ + i] =
          static_cast<float>(registry.material(i).friction.Cdf(j * step_));
    }
  }
  if (options.method == QuantileMethod::kExact) {
    for (int j = 0; j + 1 < num_points_; ++j) {
      for (int i = 0; i < num_labels_; ++i) {
        const double interpolated = 0.5 * (table_[static_cast<std::size_t>(j) * stride_ + i] +
                                           table_[static_cast<std::size_t>(j + 1) * stride_ + i]);
        // Point masses (not-walkable labels at 0) jump inside the first cell; they are handled exactly by the
        // F(0) >= target test before any interpolation.
        if (j == 0 && !registry.material(i).friction.walkable()) continue;
        cdf_interpolation_error_ = std::max(
            cdf_interpolation_error_, std::abs(interpolated - registry.material(i).friction.Cdf((j + 0.5) * step_)));
      }
    }
  }
}

float FrictionQuantileImage::CdfAt(int point, const float* p) const {
  const float* row = &table_[static_cast<std::size_t>(point) * stride_];
  // Eight independent partial sums: without them the additions form one dependent chain (the compiler may not
  // reorder float sums), which made this dot product latency-bound; with them it becomes two vector FMAs.
  float lanes[8] = {0, 0, 0, 0, 0, 0, 0, 0};
  for (int i = 0; i < stride_; i += 8) {
    for (int k = 0; k < 8; ++k) lanes[k] += p[i + k] * row[i + k];
  }
  return ((lanes[0] + lanes[4]) + (lanes[1] + lanes[5])) + ((lanes[2] + lanes[6]) + (lanes[3] + lanes[7]));
}

float FrictionQuantileImage::QuantileOfPixel(const float* p) const {
  if (options_.method == QuantileMethod::kGaussian) {
    float mean = 0.0f, second = 0.0f;
    for (int i = 0; i < num_labels_; ++i) {
      mean += p[i] * mean_[i];
      second += p[i] * second_moment_[i];
    }
    return std::max(0.0f, mean + std::sqrt(std::max(second - mean * mean, 0.0f)) * z_);
  }
  if (options_.method == QuantileMethod::kSearch) {
    // Algorithm 1: the largest grid value whose CDF does not exceed the target.
    float quantile = 0.0f;
    for (int j = 0; j < num_points_; ++j) {
      if (CdfAt(j, p) > target_) break;
      quantile = static_cast<float>(j * step_);
    }
    return quantile;
  }
  if (CdfAt(0, p) >= target_) return 0.0f;
  // The first point whose CDF reaches the target, by a branch-free binary search: the comparison result selects
  // the next base with a conditional move, so mispredicted branches do not dominate the cost.
  int base = 0;
  int length = num_points_;
  while (length > 1) {
    const int half = length / 2;
    base = CdfAt(base + half, p) < target_ ? base + half : base;
    length -= half;
  }
  const int first = std::min(base + 1, num_points_ - 1);  // F(base) < target <= F(base + 1)
  const float f_low = CdfAt(first - 1, p);
  const float f_high = CdfAt(first, p);
  if (f_high < target_) return static_cast<float>(first * step_);  // Rounding at the table's end.
  const float fraction = f_high > f_low ? (target_ - f_low) / (f_high - f_low) : 0.0f;
  return static_cast<float>((first - 1 + fraction) * step_);
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
  const int stride = stride_ > 0 ? stride_ : n;
  std::vector<std::string> errors(internal::ResolveThreadCount(options_.num_threads));
  internal::ParallelForRows(
      probabilities.rows, static_cast<int>(errors.size()), [&](int thread, int row_begin, int row_end) {
        std::vector<float> padded(stride, 0.0f);
        for (int r = row_begin; r < row_end; ++r) {
          const float* row = probabilities.ptr<float>(r);
          float* out = quantiles->ptr<float>(r);
          for (int c = 0; c < probabilities.cols; ++c) {
            const float* p = row + static_cast<std::size_t>(c) * n;
            float sum = 0.0f;
            bool in_range = true;
            for (int i = 0; i < n; ++i) {
              sum += p[i];
              in_range = in_range && p[i] >= 0.0f && p[i] <= 1.0f;
            }
            if (!in_range || !(std::abs(sum - 1.0f) <= 1e-3f)) {
              errors[thread] = "The material probabilities at pixel (" + std::to_string(r) + ", " +
                               std::to_string(c) + ") " +
                               (in_range ? "sum to " + Short(sum) + ", not 1" : std::string("leave [0, 1]")) +
                               "; normalise them (e.g. with a softmax).";
              return;
            }
            std::copy(p, p + n, padded.begin());
            out[c] = QuantileOfPixel(padded.data());
          }
        }
      });
  for (const std::string& error : errors) {
    if (!error.empty()) throw std::invalid_argument(error);
  }
}

}  // namespace cairn::perception
