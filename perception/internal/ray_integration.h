#pragma once

/// @file
/// Internal: the per-ray occupancy update shared by the cost-curve and WTA sensor models (thesis eqs. 4.13-4.17).

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "cairn/perception/internal/fast_log.h"
#include "cairn/perception/internal/parallel_rows.h"
#include "cairn/perception/occupancy/occupancy_grid.h"
#include "cairn/perception/stereo/stereo_calibration.h"

namespace cairn::perception::internal {

/// Per-ray bounds on the measurement probability and threading.
struct RayIntegrationOptions {
  double min_probability;
  double max_probability;
  double min_visibility;
  int num_threads;
};

/// Fixed-point accumulation of the per-frame mean log-odds of a cell: the rays' log-odds are quantised to
/// 2^-kLogOddsBits and summed in the high bits of an int64, the ray count in its low kCountBits bits. Integer sums
/// are associative, so the result is the same for any thread count and any split of the rows (float sums were not);
/// the quantum (1.2e-4 in log-odds, about 3e-5 in probability) is far below the sensor model's resolution.
struct PackedLogOdds {
  static constexpr int kCountBits = 22;
  static constexpr int kLogOddsBits = 13;
  /// At most this many rays may reach one cell in a frame (one per pixel, so 2^22 pixels); with |log-odds| below
  /// kMaxLogOdds, |sum| * 2^13 * 2^22 stays inside an int64.
  static constexpr int64_t kMaxRays = (int64_t{1} << kCountBits) - 1;
  static constexpr double kMaxLogOdds = 60.0;

  /// Log-odds `l` in units of the quantum, rounded half away from zero; |l| < kMaxLogOdds fits an int32.
  static int32_t Quantize(float l) {
    const float scaled = l * static_cast<float>(1 << kLogOddsBits);
    return static_cast<int32_t>(scaled + (scaled >= 0.0f ? 0.5f : -0.5f));
  }
  /// The increment of one ray with quantised log-odds q.
  static int64_t Pack(int32_t q) { return static_cast<int64_t>(q) * (int64_t{1} << kCountBits) + 1; }
  /// The mean log-odds of a sum of increments, and its ray count (0: no ray).
  static float Mean(int64_t packed, int64_t* count) {
    *count = packed & kMaxRays;
    if (*count == 0) return 0.0f;
    const int64_t sum = (packed - *count) / (int64_t{1} << kCountBits);
    return static_cast<float>(static_cast<double>(sum) /
                              (static_cast<double>(1 << kLogOddsBits) * static_cast<double>(*count)));
  }
};

/// floor to int, exact for |x| < 2^31, without a library call or a branch.
inline int FloorToInt(double x) {
  const int i = static_cast<int>(x);
  return i - (x < static_cast<double>(i) ? 1 : 0);
}

/// For every pixel whose curve(y, x, c) fills c[0..D) with a disparity distribution C(d) (d = dmin + k) and returns
/// true, walks the pixel's ray through the grid and computes, per cell, the thesis' closed form of eqs. 4.13-4.17:
/// with the target prior uniform over disparity, P(V_i | E) = T_i (the mass at or beyond cell i) and
/// P(O_i | V_i, E) = m_i / T_i, so P(O_i | E) = m_i + 0.5 (1 - T_i). The thesis' 1-D ray grid has one cell per
/// disparity; a 3-D cell stands for the disparity samples whose centres it covers (m_i their mass, as one merged
/// ray cell), or, when thinner than a disparity step, for the sample containing its middle (sharing that sample's
/// value with its neighbours), so that the result does not depend on how finely the grid cuts a disparity. Cells nearer
/// than the largest disparity are not updated (the model says nothing there); the walk stops once the remaining
/// mass is negligible, or once the cell's visibility P(V_i | E) = T_i falls below options.min_visibility. Each cell receives one update per frame, the mean of its
/// rays' log-odds, so a near cell crossed by many rays is not counted many times.
///
/// Cost: a cell standing for one disparity sample k gets the same update from every cell of the ray that stands for
/// k, so the ray's D such updates (logarithms) are computed before the walk in one vectorised loop; only near
/// cells covering several samples evaluate a logarithm during the walk. A visit is then a DDA step, one
/// division (the cell's far-side disparity) and an integer add.
template <typename Curve>
void IntegrateRays(int height, int width, int dmin, int num_disp, const StereoCalibration& calibration,
                   const Eigen::Isometry3d& X_WC, const RayIntegrationOptions& options, const Curve& curve,
                   OccupancyGrid* grid) {
  if (static_cast<int64_t>(height) * width > PackedLogOdds::kMaxRays) {
    throw std::invalid_argument("occupancy update: " + std::to_string(width) + "x" + std::to_string(height) +
                                " rays per frame exceed the per-frame limit of " +
                                std::to_string(PackedLogOdds::kMaxRays) + "; downsample the confidence volume");
  }
  const double max_log_odds = std::max(std::abs(std::log(options.min_probability / (1.0 - options.min_probability))),
                                      std::abs(std::log(options.max_probability / (1.0 - options.max_probability))));
  if (!(max_log_odds < PackedLogOdds::kMaxLogOdds)) {
    throw std::invalid_argument("occupancy update: probability limits [" + std::to_string(options.min_probability) +
                                ", " + std::to_string(options.max_probability) +
                                "] are too close to 0 or 1; use limits like [0.12, 0.97]");
  }
  // As many threads as ParallelForRows() will run (no more than rows), one accumulator each, zeroed by its own
  // thread (the first touch of its pages).
  const int threads = std::max(1, std::min(ResolveThreadCount(options.num_threads), height));
  std::vector<std::vector<int64_t>> accumulators(threads);
  const double fb = calibration.depth_times_disparity();
  const Eigen::Vector3d origin = X_WC.translation();
  const Eigen::Matrix3d R_WC = X_WC.linear();
  const double t_near = fb / (dmin + num_disp - 1 + 0.5);
  const double t_far = dmin - 0.5 > 0.0 ? fb / (dmin - 0.5) : std::numeric_limits<double>::infinity();
  const auto lo = static_cast<float>(options.min_probability);
  const auto hi = static_cast<float>(options.max_probability);
  const auto min_visibility = static_cast<float>(options.min_visibility);
  ParallelForRows(height, threads, [&](int thread, int y0, int y1) {
    std::vector<float> c(num_disp);
    std::vector<float> prefix(num_disp + 1);
    std::vector<float> beyond(num_disp);        // T of sample k: mass at or beyond it
    std::vector<int32_t> one_sample(num_disp);  // quantised log-odds of a cell standing for sample k alone
    accumulators[thread].assign(grid->num_cells(), 0);
    int64_t* accumulator = accumulators[thread].data();
    for (int y = y0; y < y1; ++y) {
      for (int x = 0; x < width; ++x) {
        if (!curve(y, x, c.data())) continue;
        prefix[0] = 0.0f;
        for (int k = 0; k < num_disp; ++k) prefix[k + 1] = prefix[k] + c[k];
        const float total = prefix[num_disp];
        if (!(total > 0.0f)) continue;
        const float inverse_total = 1.0f / total;
        // P(O_i | E) of a cell standing for samples [k_lo, k_hi], clamped, as log-odds.
        auto log_odds = [&](int k_lo, int k_hi) {
          const float mass = (prefix[k_hi + 1] - prefix[k_lo]) * inverse_total;
          float p = mass + 0.5f * (1.0f - prefix[k_hi + 1] * inverse_total);
          p = std::min(hi, std::max(lo, p));
          return LogPositive(p / (1.0f - p));
        };
        // Every cell standing for one sample k gets the same update, so the ray's D of them are computed up front
        // in one branch-free loop that the compiler vectorises (same operations as log_odds(k, k)).
        {
          const float* sums = prefix.data();
          float* visible = beyond.data();
          int32_t* single = one_sample.data();
          const float p_lo = lo;
          const float p_hi = hi;
#pragma omp simd
          for (int k = 0; k < num_disp; ++k) {
            const float visibility = sums[k + 1] * inverse_total;
            visible[k] = visibility;
            const float mass = (sums[k + 1] - sums[k]) * inverse_total;
            const float p = std::min(p_hi, std::max(p_lo, mass + 0.5f * (1.0f - visibility)));
            single[k] = PackedLogOdds::Quantize(LogPositive(p / (1.0f - p)));
          }
        }
        const Eigen::Vector3d direction =
            R_WC * Eigen::Vector3d((x - calibration.cx) / calibration.fx, (y - calibration.cy) / calibration.fy, 1.0);
        // The walk visits cells back to back, so a cell's near side is the previous cell's far side: one
        // division and one rounding per cell, and no branch on the rounding.
        double previous_t_out = -1.0;
        double previous_delta_out = 0.0;
        int previous_floor_out = 0;
        grid->Traverse(origin, direction, t_near, t_far, [&](std::size_t index, double t_in, double t_out) {
          // The disparity samples this cell stands for: those whose centres it covers, or, for a cell thinner
          // than a disparity step, the one containing its middle.
          const bool continues = t_in == previous_t_out;
          const double delta_in = continues ? previous_delta_out : fb / t_in - dmin;  // near side
          const int floor_in = continues ? previous_floor_out : FloorToInt(delta_in);
          const double delta_out = fb / t_out - dmin;  // far side: smaller disparity
          const int floor_out = FloorToInt(delta_out);
          previous_t_out = t_out;
          previous_delta_out = delta_out;
          previous_floor_out = floor_out;
          int k_lo = floor_out + (delta_out > static_cast<double>(floor_out) ? 1 : 0);  // ceil(delta_out)
          int k_hi = floor_in;
          // No sample centre in [delta_out, delta_in]: both lie in (floor_in, floor_in + 1), and so does the
          // middle, whose std::lround is floor_in or floor_in + 1.
          const double middle = 0.5 * (delta_in + delta_out);
          const double fraction = middle - static_cast<double>(floor_in);
          const int rounded = floor_in + static_cast<int>((fraction > 0.5) | ((fraction == 0.5) & (middle >= 0.0)));
          const bool thin = k_lo > k_hi;
          k_lo = thin ? rounded : k_lo;
          k_hi = thin ? rounded : k_hi;
          k_lo = std::max(k_lo, 0);
          k_hi = std::min(k_hi, num_disp - 1);
          if (k_lo > k_hi) return k_hi >= 0;  // entirely nearer than the range: keep walking; farther: stop
          const float visibility = beyond[k_hi];  // T_i: mass at or beyond the cell
          // Cells hidden with high probability learn only the 0.5 prior from this ray; skipping them keeps the
          // slight excess of P(O|V) in the cost curve's tail from accumulating behind surfaces over frames.
          if (visibility < min_visibility) return false;
          accumulator[index] += PackedLogOdds::Pack(k_lo == k_hi ? one_sample[k_lo]
                                                                 : PackedLogOdds::Quantize(log_odds(k_lo, k_hi)));
          return visibility > 1e-4f;
        });
      }
    }
  });
  // Integer sums: splitting the cells across threads cannot change the result. One contiguous chunk per thread.
  const std::size_t num_cells = grid->num_cells();
  ParallelForRows(threads, threads, [&](int, int chunk_begin, int chunk_end) {
    const std::size_t begin = num_cells * static_cast<std::size_t>(chunk_begin) / static_cast<std::size_t>(threads);
    const std::size_t end = num_cells * static_cast<std::size_t>(chunk_end) / static_cast<std::size_t>(threads);
    for (std::size_t i = begin; i < end; ++i) {
      int64_t packed = 0;
      for (int t = 0; t < threads; ++t) packed += accumulators[t][i];
      int64_t count = 0;
      const float mean = PackedLogOdds::Mean(packed, &count);
      if (count > 0) grid->Update(i, mean);
    }
  });
}

}  // namespace cairn::perception::internal
