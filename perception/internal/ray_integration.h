#pragma once

/// @file
/// Internal: the per-ray occupancy update shared by the cost-curve and WTA sensor models (thesis eqs. 4.13-4.17).

#include <cmath>
#include <cstdint>
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
template <typename Curve>
void IntegrateRays(int height, int width, int dmin, int num_disp, const StereoCalibration& calibration,
                   const Eigen::Isometry3d& X_WC, const RayIntegrationOptions& options, const Curve& curve,
                   OccupancyGrid* grid) {
  const int threads = ResolveThreadCount(options.num_threads);
  // Sum and count side by side: one cache line per cell visit instead of two.
  struct Accumulator {
    float sum;
    uint32_t count;
  };
  std::vector<std::vector<Accumulator>> accumulators(threads, std::vector<Accumulator>(grid->num_cells(), {0.0f, 0}));
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
    Accumulator* accumulator = accumulators[thread].data();
    for (int y = y0; y < y1; ++y) {
      for (int x = 0; x < width; ++x) {
        if (!curve(y, x, c.data())) continue;
        prefix[0] = 0.0f;
        for (int k = 0; k < num_disp; ++k) prefix[k + 1] = prefix[k] + c[k];
        const float total = prefix[num_disp];
        if (!(total > 0.0f)) continue;
        const float inverse_total = 1.0f / total;
        const Eigen::Vector3d direction =
            R_WC * Eigen::Vector3d((x - calibration.cx) / calibration.fx, (y - calibration.cy) / calibration.fy, 1.0);
        // The walk visits cells back to back, so a cell's near side is the previous cell's far side: one
        // division per cell.
        double previous_t_out = -1.0;
        double previous_delta_out = 0.0;
        grid->Traverse(origin, direction, t_near, t_far, [&](std::size_t index, double t_in, double t_out) {
          // The disparity samples this cell stands for: those whose centres it covers, or, for a cell thinner
          // than a disparity step, the one containing its middle.
          const double delta_in = t_in == previous_t_out ? previous_delta_out : fb / t_in - dmin;  // near side
          const double delta_out = fb / t_out - dmin;  // far side: smaller disparity
          previous_t_out = t_out;
          previous_delta_out = delta_out;
          int k_lo = static_cast<int>(std::ceil(delta_out));
          int k_hi = static_cast<int>(std::floor(delta_in));
          if (k_lo > k_hi) k_lo = k_hi = static_cast<int>(std::lround(0.5 * (delta_in + delta_out)));
          k_lo = std::max(k_lo, 0);
          k_hi = std::min(k_hi, num_disp - 1);
          if (k_lo > k_hi) return k_hi >= 0;  // entirely nearer than the range: keep walking; farther: stop
          const float beyond = prefix[k_hi + 1] * inverse_total;  // T_i: mass at or beyond the cell
          // Cells hidden with high probability learn only the 0.5 prior from this ray; skipping them keeps the
          // slight excess of P(O|V) in the cost curve's tail from accumulating behind surfaces over frames.
          if (beyond < min_visibility) return false;
          const float mass = (prefix[k_hi + 1] - prefix[k_lo]) * inverse_total;
          float p = mass + 0.5f * (1.0f - beyond);
          p = std::min(hi, std::max(lo, p));
          accumulator[index].sum += LogPositive(p / (1.0f - p));
          ++accumulator[index].count;
          return beyond > 1e-4f;
        });
      }
    }
  });
  for (std::size_t i = 0; i < grid->num_cells(); ++i) {
    float s = 0.0f;
    int n = 0;
    for (int t = 0; t < threads; ++t) {
      s += accumulators[t][i].sum;
      n += static_cast<int>(accumulators[t][i].count);
    }
    if (n > 0) grid->Update(i, s / static_cast<float>(n));
  }
}

}  // namespace cairn::perception::internal
