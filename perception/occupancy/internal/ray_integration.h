#pragma once

/// @file
/// Internal: the per-ray occupancy update shared by the cost-curve and WTA sensor models (thesis eqs. 4.13-4.17).

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "cairn/common/parallel_for.h"
#include "cairn/perception/internal/multiversion.h"
#include "cairn/perception/occupancy/grid_walk.h"
#include "cairn/perception/occupancy/internal/fast_log.h"
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

/// The quantised log-odds of clamped occupancy probabilities: q[i] = Quantize(log(p[i] / (1 - p[i]))), in one loop
/// that the compiler vectorises.
inline void QuantizedLogOdds(const float* p, int n, int32_t* q) {
#pragma omp simd
  for (int i = 0; i < n; ++i) q[i] = PackedLogOdds::Quantize(LogPositive(p[i] / (1.0f - p[i])));
}

/// The per-frame accumulators of IntegrateRays(), one per worker thread, kept by the calling thread between frames
/// (thread-local storage): a stream of frames then neither allocates nor page-faults them (8 bytes per grid cell
/// per worker, 12.6 MB each for a 128 x 64 x 192 grid) each frame. They are all zero between calls: the merge
/// clears what it reads. The memory is held until the calling thread exits.
struct RayAccumulators {
  std::vector<std::vector<int64_t>> per_thread;
  bool zero{true};  // false while a call is using them (and left false if it threw)

  static RayAccumulators& ForThisThread() {
    thread_local RayAccumulators accumulators;
    return accumulators;
  }
  /// Makes `threads` zero accumulators of `cells` cells available.
  void Prepare(int threads, std::size_t cells) {
    if (per_thread.size() < static_cast<std::size_t>(threads)) per_thread.resize(threads);
    for (int t = 0; t < threads; ++t) {
      if (!zero || per_thread[t].size() != cells) per_thread[t].assign(cells, 0);
    }
    zero = false;
  }
};

/// One worker's share of IntegrateRays(), a row of pixels at a time: the row's curves and tables, a batch of one
/// walk's cells, and the near cells waiting for their logarithm. Owns no accumulator: adds to the one it is given.
class RayIntegrator {
 public:
  /// The frame's constants.
  struct Frame {
    const OccupancyGrid* grid;
    Eigen::Vector3d origin;  // of the rays, in the grid's frame
    Eigen::Matrix3d R_WC;    // the camera's orientation: pixel (x, y) looks along R_WC (x', y', 1)
    double fx, fy, cx, cy;   // intrinsics: x' = (x - cx) / fx, y' = (y - cy) / fy
    int width;               // pixels per row
    double fb;               // focal length times baseline: depth = fb / disparity
    int dmin;                // disparity of sample 0
    int num_disp;            // samples
    double t_near;           // depth of the near edge of the largest disparity sample
    double t_far;            // depth of the far edge of the smallest
    float min_probability;
    float max_probability;
    float min_visibility;
  };

  RayIntegrator(const Frame& frame, int64_t* accumulator)
      : frame_(frame),
        accumulator_(accumulator),
        max_cells_per_ray_(frame.grid->dims().sum() + 3),
        capacity_(std::max(4096, 2 * max_cells_per_ray_)),
        row_stride_(frame.num_disp + 1),
        row_(static_cast<std::size_t>(frame.width) * row_stride_, 0.0f),
        rays_(frame.width),
        table_p_(static_cast<std::size_t>(frame.width) * frame.num_disp),
        table_q_(table_p_.size()),
        table_(table_p_.size()),
        cell_index_(max_cells_per_ray_),
        cell_depth_(max_cells_per_ray_),
        pending_index_(capacity_),
        pending_p_(capacity_),
        pending_q_(capacity_) {}

  /// Where the curve C(dmin + k), k in [0, D), of pixel x of the next row goes.
  float* curve(int x) { return row_.data() + static_cast<std::size_t>(x) * row_stride_ + 1; }
  /// Integrates the rays of row y whose curves were written (has_curve[x] != 0).
  void IntegrateRow(int y, const uint8_t* has_curve);
  /// Adds the near cells still waiting for their logarithm to the accumulator; call after the last row.
  void Flush();

 private:
  // Disparities in fixed point, 2^32 units per pixel.
  static constexpr int kDisparityBits = 32;
  static constexpr int64_t kDisparityOne = int64_t{1} << kDisparityBits;

  // What the walk of a ray needs.
  struct Ray {
    float inverse_total;  // 1 / the curve's total mass
    int k_hidden;         // samples [0, k_hidden] are hidden below min_visibility: the walk stops there
    int k_negligible;     // samples [0, k_negligible] have visibility below 1e-4: the walk stops after one
    double t_thin;        // beyond this depth every cell stands for one sample, at most k_top
    int k_top;
    std::size_t table;    // where the ray's run of table_ starts (sample k_hidden + 1)
    GridWalk walk;        // through the grid, over the depths of the disparity range
    bool active;          // false if the ray updates nothing
  };

  // Walks the ray of a pixel whose prefix sums are prefix[k] (mass of samples [0, k)).
  void IntegrateRay(const float* prefix, Ray* ray);

  const Frame frame_;
  int64_t* const accumulator_;
  const int max_cells_per_ray_;  // bound on the cells a walk visits
  const int capacity_;           // of the batch of near cells
  const int row_stride_;
  std::vector<float> row_;  // per pixel: 0, then the curve, turned in place into its prefix sums
  std::vector<Ray> rays_;   // per pixel
  // The row's tables of far-cell updates, one run of samples (k_hidden, k_top] per ray: P(O | E) of a cell
  // standing for one sample, its quantised log-odds, its packed increment.
  std::vector<float> table_p_;
  std::vector<int32_t> table_q_;
  std::vector<int64_t> table_;
  std::vector<std::size_t> cell_index_;  // one batch of a walk's cells
  std::vector<double> cell_depth_;       // and their far sides: depths, then disparities
  std::vector<std::size_t> pending_index_;  // near cells waiting for their logarithm
  std::vector<float> pending_p_;            // their P(O | E)
  std::vector<int32_t> pending_q_;
  int num_pending_{0};
};

CAIRN_MULTIVERSION inline void RayIntegrator::Flush() {
  QuantizedLogOdds(pending_p_.data(), num_pending_, pending_q_.data());
  for (int i = 0; i < num_pending_; ++i) accumulator_[pending_index_[i]] += PackedLogOdds::Pack(pending_q_[i]);
  num_pending_ = 0;
}

CAIRN_MULTIVERSION inline void RayIntegrator::IntegrateRow(int y, const uint8_t* has_curve) {
  const int num_disp = frame_.num_disp;
  const int width = frame_.width;
  // The row's curves become prefix sums first (each a serial chain of dependent additions), eight pixels at a time
  // with the running sums in registers, so that eight chains advance together; the walks come after. Columns
  // without a curve this row are cleared rather than summed again.
  for (int x = 0; x < width; ++x) {
    if (!has_curve[x]) std::fill_n(row_.data() + static_cast<std::size_t>(x) * row_stride_, row_stride_, 0.0f);
  }
  constexpr int kLanes = 8;
  int x = 0;
  for (; x + kLanes <= width; x += kLanes) {
    float* column[kLanes];
    float sum[kLanes];
    for (int i = 0; i < kLanes; ++i) {
      column[i] = row_.data() + static_cast<std::size_t>(x + i) * row_stride_;
      sum[i] = 0.0f;
    }
    for (int k = 1; k <= num_disp; ++k) {
      for (int i = 0; i < kLanes; ++i) {
        sum[i] += column[i][k];
        column[i][k] = sum[i];
      }
    }
  }
  for (; x < width; ++x) {
    float* column = row_.data() + static_cast<std::size_t>(x) * row_stride_;
    float sum = 0.0f;
    for (int k = 1; k <= num_disp; ++k) {
      sum += column[k];
      column[k] = sum;
    }
  }
  // The visibility T of sample k (the mass at or beyond it, prefix[k + 1] / total) grows with k, so the samples
  // hidden below min_visibility, where a walk stops, are [0, k_hidden], and those below 1e-4, where it stops after
  // one more update, [0, k_negligible]. (C(d) >= 0, and rounding cannot make a sum of such terms decrease.)
  const float min_visibility = frame_.min_visibility;
  for (int x = 0; x < width; ++x) {
    Ray& ray = rays_[x];
    const float* prefix = row_.data() + static_cast<std::size_t>(x) * row_stride_;
    ray.active = has_curve[x] && prefix[num_disp] > 0.0f;
    if (!ray.active) continue;
    const float inverse_total = 1.0f / prefix[num_disp];
    int num_hidden = 0;
    int num_negligible = 0;
#pragma omp simd reduction(+ : num_hidden, num_negligible)
    for (int k = 0; k < num_disp; ++k) {
      const float visibility = prefix[k + 1] * inverse_total;
      num_hidden += visibility < min_visibility ? 1 : 0;
      num_negligible += visibility <= 1e-4f ? 1 : 0;
    }
    ray.inverse_total = inverse_total;
    ray.k_hidden = num_hidden - 1;
    ray.k_negligible = num_negligible - 1;
    ray.active = ray.k_hidden < num_disp - 1;  // else every sample is hidden: no cell is updated
  }
  // The walks' starts, and the rays' runs of the table: P(O | E) of a cell standing for one sample k alone, for the
  // samples a far cell can stand for and the walk can update.
  const OccupancyGrid& grid = *frame_.grid;
  const double resolution = grid.resolution();
  const double fb = frame_.fb;
  const double y_camera = (y - frame_.cy) / frame_.fy;
  const float p_lo = frame_.min_probability;
  const float p_hi = frame_.max_probability;
  float* p = table_p_.data();
  for (int x = 0; x < width; ++x) {
    Ray& ray = rays_[x];
    if (!ray.active) continue;
    const Eigen::Vector3d direction = frame_.R_WC * Eigen::Vector3d((x - frame_.cx) / frame_.fx, y_camera, 1.0);
    ray.active = ray.walk.Start(grid.min_corner(), resolution, grid.dims(), frame_.origin, direction, frame_.t_near,
                                frame_.t_far);
    if (!ray.active) continue;
    // A cell spans at most `span` in t (the cell side over the direction's largest component), so beyond t_thin,
    // where such a span is less than one disparity step (fb span / (t (t + span)) < 1), a cell covers at most one
    // sample centre and stands for the sample containing its middle, which is at most k_top.
    const double span = resolution / direction.cwiseAbs().maxCoeff();
    ray.t_thin = 0.5 * (std::sqrt(span * span + 4.0 * fb * span) - span) * (1.0 + 1e-9);
    ray.k_top = std::min(num_disp - 1, FloorToInt(fb / ray.t_thin - frame_.dmin + 0.5));
    ray.table = static_cast<std::size_t>(p - table_p_.data());
    const float* prefix = row_.data() + static_cast<std::size_t>(x) * row_stride_;
    const float inverse_total = ray.inverse_total;
    const int k_end = ray.k_top + 1;
    for (int k = ray.k_hidden + 1; k < k_end; ++k) {
      const float visibility = prefix[k + 1] * inverse_total;
      const float mass = (prefix[k + 1] - prefix[k]) * inverse_total;
      *p++ = std::min(p_hi, std::max(p_lo, mass + 0.5f * (1.0f - visibility)));
    }
  }
  const int table_size = static_cast<int>(p - table_p_.data());
  QuantizedLogOdds(table_p_.data(), table_size, table_q_.data());
  for (int i = 0; i < table_size; ++i) table_[i] = PackedLogOdds::Pack(table_q_[i]);
  for (int x = 0; x < width; ++x) {
    if (!rays_[x].active) continue;
    if (num_pending_ + max_cells_per_ray_ > capacity_) Flush();
    IntegrateRay(row_.data() + static_cast<std::size_t>(x) * row_stride_, &rays_[x]);
  }
}

CAIRN_MULTIVERSION inline void RayIntegrator::IntegrateRay(const float* prefix, Ray* ray) {
  GridWalk& walk = ray->walk;
  const int num_disp = frame_.num_disp;
  const float inverse_total = ray->inverse_total;
  const int k_hidden = ray->k_hidden;
  const int k_negligible = ray->k_negligible;
  // t is the depth, so a side of a cell at fixed-point depth T has the disparity fb / (T unit), here in fixed point
  // with 2^32 units per pixel (below 2^52, so exact in a double, for any disparity below 2^20). Floors, ceilings and
  // the rounding of a cell's middle are then integer shifts: (d_in + d_out + rounding_bias) >> 33 is
  // floor((d_in + d_out) / 2 + 1/2) - dmin, the sample containing the middle.
  const double fb_fixed = frame_.fb * walk.scale() * kDisparityOne;
  const int64_t dmin_fixed = static_cast<int64_t>(frame_.dmin) * kDisparityOne;
  const int64_t rounding_bias = kDisparityOne - 2 * dmin_fixed;
  int64_t d_in = static_cast<int64_t>(fb_fixed / static_cast<double>(walk.position()));  // the current cell's near side

  // A near cell stands for the samples whose centres it covers if two or more, else for the one containing its
  // middle (also the one centre it covers, if any: a cell covering exactly one centre is less than two steps wide).
  // Its P(O | E) joins the batch, whose logarithms are taken together in one vectorised loop. Returns whether the
  // walk goes on.
  std::size_t* const pending_index = pending_index_.data();
  float* const pending_p = pending_p_.data();
  const float p_lo = frame_.min_probability;
  const float p_hi = frame_.max_probability;
  auto near_cell = [&](std::size_t index, int64_t d_out) {
    const int middle = std::min(num_disp, static_cast<int>((d_in + d_out + rounding_bias) >> (kDisparityBits + 1)));
    const int k_hi = std::min(num_disp - 1, static_cast<int>((d_in - dmin_fixed) >> kDisparityBits));
    const int k_lo = std::max(0, static_cast<int>((d_out - dmin_fixed + kDisparityOne - 1) >> kDisparityBits));
    d_in = d_out;
    const bool several = k_lo < k_hi;
    const int first = several ? k_lo : middle;
    const int last = several ? k_hi : middle;
    if (last <= k_hidden) return false;
    if (last == num_disp) return true;  // nearer than the range: the model says nothing
    const float mass = (prefix[last + 1] - prefix[first]) * inverse_total;
    pending_index[num_pending_] = index;
    pending_p[num_pending_] = std::min(p_hi, std::max(p_lo, mass + 0.5f * (1.0f - prefix[last + 1] * inverse_total)));
    ++num_pending_;
    return last > k_negligible;
  };
  // A far cell stands for one sample and takes its update from the ray's table, whose run starts at k_hidden + 1
  // (the offset is folded into the rounding). Cells hidden with high probability learn only the 0.5 prior from this
  // ray; skipping them keeps the slight excess of P(O|V) in the cost curve's tail from accumulating behind surfaces
  // over frames.
  int64_t* const accumulator = accumulator_;
  const int64_t* const increment = table_.data() + ray->table;
  const int k_base = k_hidden + 1;
  const int64_t table_bias = rounding_bias - static_cast<int64_t>(k_base) * (2 * kDisparityOne);
  const int k_last = std::max(k_hidden, k_negligible) - k_base;
  const int k_table_top = ray->k_top - k_base;
  auto far_cell = [&](std::size_t index, int64_t d_out) {
    const int k = static_cast<int>((d_in + d_out + table_bias) >> (kDisparityBits + 1));
    d_in = d_out;
    if (k <= k_last) {  // the last cell of the walk: updated only if not hidden
      if (k >= 0) accumulator[index] += increment[k];
      return false;
    }
    accumulator[index] += increment[k];
    return true;
  };

  // Near cells are walked and updated in two loops, one batch per ray: the walk records the cells and their far
  // sides, the divisions run in vector registers, and each loop keeps its few variables in registers (in one loop,
  // they did not fit). The batch ends where the walk may stop at the latest: at the depth where the disparity falls
  // to the far edge of the last sample it updates. Cells between that depth and t_thin, if any, and the far cells
  // are walked and updated cell by cell.
  std::size_t* const cells = cell_index_.data();
  double* const depths = cell_depth_.data();
  auto walk_batch = [&](std::int64_t until, const auto& cell) {
    int n = 0;
    const bool more = walk.Walk(until, [&](std::size_t index, std::int64_t exit) {
      cells[n] = index;
      depths[n] = static_cast<double>(exit);
      ++n;
      return true;
    });
#pragma omp simd
    for (int i = 0; i < n; ++i) depths[i] = fb_fixed / depths[i];  // now the disparities, fixed point
    for (int i = 0; i < n; ++i) {
      if (!cell(cells[i], static_cast<int64_t>(depths[i]))) return false;
    }
    return more;
  };
  auto walk_precisely = [&](std::int64_t until, const auto& cell) {
    return walk.Walk(until, [&](std::size_t index, std::int64_t exit) {
      return cell(index, static_cast<int64_t>(fb_fixed / static_cast<double>(exit)));
    });
  };
  const double last_edge = frame_.dmin + std::max(k_hidden, k_negligible) + 0.5;  // disparity
  const std::int64_t stop = walk.ToFixedSaturated(frame_.fb / last_edge);
  const std::int64_t thin = walk.ToFixedSaturated(ray->t_thin);
  if (!walk_batch(std::min(thin, stop), near_cell)) return;
  if (!walk_precisely(thin, near_cell)) return;
  // A far cell's middle is at most the disparity at t_thin, so its sample is at most k_top, the table's last entry.
  // Disparities only decrease along the walk: clamping the near side of the first far cell so that the rounding
  // cannot give more than k_top (a change only at a tie) makes that hold for every far cell, without a check.
  const int64_t d_top = ((static_cast<int64_t>(k_table_top) + 1) * (2 * kDisparityOne) - table_bias) / 2 - 1;
  d_in = std::min(d_in, d_top);
  walk_precisely(std::numeric_limits<std::int64_t>::max(), far_cell);
}

/// For every pixel whose curve(y, x, c) fills c[0..D) with a disparity distribution C(d) >= 0 (d = dmin + k) and
/// returns true, walks the pixel's ray through the grid and computes, per cell, the thesis' closed form of eqs.
/// 4.13-4.17: with the target prior uniform over disparity, P(V_i | E) = T_i (the mass at or beyond cell i) and
/// P(O_i | V_i, E) = m_i / T_i, so P(O_i | E) = m_i + 0.5 (1 - T_i). The thesis' 1-D ray grid has one cell per
/// disparity; a 3-D cell stands for the disparity samples whose centres it covers if two or more (m_i their mass, as
/// one merged ray cell), else for the sample containing its middle (the mean of the disparities fb / t of its two
/// sides, a middle on a sample edge going to the larger disparity): thin cells share their sample's value with
/// their neighbours, and a cell covering exactly one centre stands for that one, so the result does not depend on
/// how finely the grid cuts a disparity. Cells nearer than the largest disparity are not updated (the model says
/// nothing there); the walk stops before a cell whose visibility T_i = P(V_i | E) is below options.min_visibility,
/// and after one whose visibility is at most 1e-4. Cells the ray only touches at an edge or corner are not visited
/// (internal::GridWalk). Each cell receives one update per frame, the mean of its rays' log-odds, so a near cell
/// crossed by many rays is not counted many times; the sums are integers, so the grid is the same, bit for bit, for
/// any thread count.
///
/// Cost, about 32 M cell visits for 640 x 480 rays: t along a ray is the camera depth, so a cell's disparities are
/// fb / t at its sides, one division per cell (in fixed point; the near side is the previous cell's far side). Far
/// from the camera (beyond t_thin) a cell can cover at most one sample centre and stands for one sample, and every
/// cell standing for sample k gets the same update: a row's such updates, for the samples each ray can reach, are
/// computed before its walks in one vectorised loop, and a far visit is a DDA step, that division and an integer
/// add. The near cells (a quarter of the visits) are recorded per ray and updated in a second loop, their
/// logarithms batched. Rows are interleaved across the threads, each adding to its own accumulator (kept between
/// calls, see RayAccumulators).
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
  // The per-ray arithmetic is in float: a limit that rounds to 0 or 1 there would give infinite log-odds.
  const float float_min = static_cast<float>(options.min_probability);
  const float float_max = static_cast<float>(options.max_probability);
  if (!(max_log_odds < PackedLogOdds::kMaxLogOdds) || !(float_min > 0.0f) || !(float_max < 1.0f) ||
      !(float_max / (1.0f - float_max) < std::numeric_limits<float>::infinity())) {
    throw std::invalid_argument("occupancy update: probability limits [" + std::to_string(options.min_probability) +
                                ", " + std::to_string(options.max_probability) +
                                "] are too close to 0 or 1; use limits like [0.12, 0.97]");
  }
  // The fixed-point disparities of the walk need them below 2^20.
  const int64_t max_disparity = static_cast<int64_t>(dmin) + num_disp - 1;
  if (max_disparity >= (int64_t{1} << 20)) {
    throw std::invalid_argument("occupancy update: max disparity " + std::to_string(max_disparity) +
                                " is 2^20 or more; pass the disparity range the matcher searched");
  }
  // As many threads as ParallelFor() will run (no more than rows), one accumulator each.
  const int threads = std::max(1, std::min(ResolveThreadCount(options.num_threads), height));
  const std::size_t num_cells = grid->num_cells();
  RayAccumulators& accumulators = RayAccumulators::ForThisThread();
  accumulators.Prepare(threads, num_cells);
  RayIntegrator::Frame frame;
  frame.grid = grid;
  frame.origin = X_WC.translation();
  frame.R_WC = X_WC.linear();
  frame.fx = calibration.fx;
  frame.fy = calibration.fy;
  frame.cx = calibration.cx;
  frame.cy = calibration.cy;
  frame.width = width;
  frame.fb = calibration.depth_times_disparity();
  frame.dmin = dmin;
  frame.num_disp = num_disp;
  frame.t_near = frame.fb / (dmin + num_disp - 1 + 0.5);
  frame.t_far = dmin - 0.5 > 0.0 ? frame.fb / (dmin - 0.5) : std::numeric_limits<double>::infinity();
  frame.min_probability = static_cast<float>(options.min_probability);
  frame.max_probability = static_cast<float>(options.max_probability);
  frame.min_visibility = static_cast<float>(options.min_visibility);
  // Thread t takes rows t, t + threads, ...: the cost of a row varies smoothly over the image (with the depth of
  // what it sees), so interleaved rows balance the threads where contiguous bands did not.
  ParallelFor(threads, threads, [&](int thread, int, int) {
    RayIntegrator integrator(frame, accumulators.per_thread[thread].data());
    std::vector<uint8_t> has_curve(width);
    for (int y = thread; y < height; y += threads) {
      for (int x = 0; x < width; ++x) has_curve[x] = curve(y, x, integrator.curve(x)) ? 1 : 0;
      integrator.IntegrateRow(y, has_curve.data());
    }
    integrator.Flush();
  });
  // Integer sums: splitting the cells across threads cannot change the result. One contiguous chunk per thread,
  // which also clears the accumulators for the next call.
  ParallelFor(threads, threads, [&](int, int chunk_begin, int chunk_end) {
    const std::size_t begin = num_cells * static_cast<std::size_t>(chunk_begin) / static_cast<std::size_t>(threads);
    const std::size_t end = num_cells * static_cast<std::size_t>(chunk_end) / static_cast<std::size_t>(threads);
    for (std::size_t i = begin; i < end; ++i) {
      int64_t packed = 0;
      for (int t = 0; t < threads; ++t) packed += accumulators.per_thread[t][i];
      if (packed == 0) continue;  // no ray (a ray's count makes the low bits nonzero): nothing to clear either
      for (int t = 0; t < threads; ++t) accumulators.per_thread[t][i] = 0;
      int64_t count = 0;
      const float mean = PackedLogOdds::Mean(packed, &count);
      if (count > 0) grid->Update(i, mean);
    }
  });
  accumulators.zero = true;
}

}  // namespace cairn::perception::internal
