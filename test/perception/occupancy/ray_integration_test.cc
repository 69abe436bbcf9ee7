#include "cairn/perception/occupancy/internal/ray_integration.h"

#include <cmath>
#include <random>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

namespace cairn::perception {
namespace {

using internal::PackedLogOdds;

// A textbook 3-D DDA in double precision (branches, no fixed point): the cells crossed by origin + t direction for
// t in [t_begin, t_end], each with the t where the ray enters and leaves it.
template <typename Visit>
void ReferenceWalk(const OccupancyGrid& grid, const Eigen::Vector3d& origin, const Eigen::Vector3d& direction,
                   double t_begin, double t_end, const Visit& visit) {
  double t0 = t_begin;
  double t1 = t_end;
  for (int a = 0; a < 3; ++a) {
    double ta = (grid.min_corner()[a] - origin[a]) / direction[a];
    double tb = (grid.max_corner()[a] - origin[a]) / direction[a];
    if (ta > tb) std::swap(ta, tb);
    t0 = std::max(t0, ta);
    t1 = std::min(t1, tb);
  }
  if (!(t0 < t1)) return;
  const Eigen::Vector3d start = origin + t0 * direction;
  Eigen::Vector3i cell;
  Eigen::Vector3d next;
  Eigen::Vector3d spacing;
  Eigen::Vector3i step;
  for (int a = 0; a < 3; ++a) {
    cell[a] = std::clamp(static_cast<int>(std::floor((start[a] - grid.min_corner()[a]) / grid.resolution())), 0,
                         grid.dims()[a] - 1);
    step[a] = direction[a] > 0.0 ? 1 : -1;
    const double boundary = grid.min_corner()[a] + (cell[a] + (step[a] > 0 ? 1 : 0)) * grid.resolution();
    next[a] = (boundary - origin[a]) / direction[a];
    spacing[a] = grid.resolution() / std::abs(direction[a]);
  }
  double t = t0;
  while (t < t1) {
    int axis = 0;
    if (next[1] < next[axis]) axis = 1;
    if (next[2] < next[axis]) axis = 2;
    const double t_exit = std::min(next[axis], t1);
    if (t_exit > t && !visit(grid.Index(cell), t, t_exit)) return;
    t = t_exit;
    cell[axis] += step[axis];
    next[axis] += spacing[axis];
    if (cell[axis] < 0 || cell[axis] >= grid.dims()[axis]) return;
  }
}

// The occupancy update of IntegrateRays() as documented, cell by cell in double precision: per cell, the samples
// whose centres it covers if two or more, else the one containing its middle; P(O | E) = m + 0.5 (1 - T); the walk
// stops before a cell whose visibility is below min_visibility, and after one whose visibility is at most 1e-4.
void ReferenceIntegrate(const std::vector<std::vector<float>>& curves, int width, int dmin,
                        const StereoCalibration& calibration, const Eigen::Isometry3d& X_WC,
                        const internal::RayIntegrationOptions& options, OccupancyGrid* grid) {
  const int num_disp = static_cast<int>(curves[0].size());
  const double fb = calibration.depth_times_disparity();
  const auto lo = static_cast<float>(options.min_probability);
  const auto hi = static_cast<float>(options.max_probability);
  std::vector<int64_t> accumulator(grid->num_cells(), 0);
  for (std::size_t pixel = 0; pixel < curves.size(); ++pixel) {
    const std::vector<float>& c = curves[pixel];
    std::vector<float> prefix(num_disp + 1, 0.0f);
    for (int k = 0; k < num_disp; ++k) prefix[k + 1] = prefix[k] + c[k];
    if (!(prefix[num_disp] > 0.0f)) continue;
    const float inverse_total = 1.0f / prefix[num_disp];
    const int x = static_cast<int>(pixel) % width;
    const int y = static_cast<int>(pixel) / width;
    const Eigen::Vector3d direction =
        X_WC.linear() *
        Eigen::Vector3d((x - calibration.cx) / calibration.fx, (y - calibration.cy) / calibration.fy, 1.0);
    ReferenceWalk(*grid, X_WC.translation(), direction, fb / (dmin + num_disp - 0.5), fb / (dmin - 0.5),
                  [&](std::size_t index, double t_in, double t_out) {
                    const double delta_in = fb / t_in - dmin;
                    const double delta_out = fb / t_out - dmin;
                    int first = std::max(0, static_cast<int>(std::ceil(delta_out)));
                    int last = std::min(num_disp - 1, static_cast<int>(std::floor(delta_in)));
                    if (first >= last) {
                      first = last = static_cast<int>(std::floor(0.5 * (delta_in + delta_out) + 0.5));
                      if (last >= num_disp) return true;  // nearer than the range
                      if (last < 0) return false;         // farther
                    }
                    const float visibility = prefix[last + 1] * inverse_total;
                    if (visibility < static_cast<float>(options.min_visibility)) return false;
                    const float mass = (prefix[last + 1] - prefix[first]) * inverse_total;
                    const float p = std::min(hi, std::max(lo, mass + 0.5f * (1.0f - visibility)));
                    accumulator[index] +=
                        PackedLogOdds::Pack(PackedLogOdds::Quantize(internal::LogPositive(p / (1.0f - p))));
                    return visibility > 1e-4f;
                  });
  }
  for (std::size_t i = 0; i < accumulator.size(); ++i) {
    int64_t count = 0;
    const float mean = PackedLogOdds::Mean(accumulator[i], &count);
    if (count > 0) grid->Update(i, mean);
  }
}

// Random peaked curves (a few lumps over a floor), some pixels without a measurement or without mass.
std::vector<std::vector<float>> RandomCurves(int pixels, int num_disp, std::vector<bool>* measured) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
  std::vector<std::vector<float>> curves(pixels, std::vector<float>(num_disp, 0.0f));
  measured->assign(pixels, true);
  for (int i = 0; i < pixels; ++i) {
    if (i % 97 == 3) (*measured)[i] = false;
    if (i % 89 == 5) continue;  // all zero: no mass
    for (int k = 0; k < num_disp; ++k) curves[i][k] = 0.01f * uniform(rng);
    for (int lump = 0; lump < 2; ++lump) {
      const int centre = static_cast<int>(uniform(rng) * num_disp);
      for (int k = std::max(0, centre - 2); k < std::min(num_disp, centre + 3); ++k) {
        curves[i][k] += uniform(rng) / (1.0f + std::abs(k - centre));
      }
    }
    if (i % 13 == 7) curves[i][0] += 5.0f;  // mass at the far end: the walk runs to t_far
  }
  return curves;
}

class RayIntegrationTest : public ::testing::Test {
 protected:
  static constexpr int kWidth = 48;
  static constexpr int kHeight = 36;
  static constexpr int kDmin = 1;
  static constexpr int kNumDisp = 32;

  RayIntegrationTest() : curves_(RandomCurves(kWidth * kHeight, kNumDisp, &measured_)) {
    // A rotated camera away from the grid's planes, so that no ray meets a cell edge exactly.
    X_WC_.linear() = (Eigen::AngleAxisd(0.31, Eigen::Vector3d::UnitY()) *
                      Eigen::AngleAxisd(-0.17, Eigen::Vector3d::UnitX()) *
                      Eigen::AngleAxisd(0.05, Eigen::Vector3d::UnitZ()))
                         .toRotationMatrix();
    X_WC_.translation() = Eigen::Vector3d(0.013, -0.027, 0.041);
  }

  OccupancyGrid MakeGrid() const {
    return OccupancyGrid(Eigen::Vector3d(-4.0, -3.0, -0.5), 0.1, Eigen::Vector3i(80, 60, 130));
  }

  OccupancyGrid Integrate(const internal::RayIntegrationOptions& options) const {
    OccupancyGrid grid = MakeGrid();
    internal::IntegrateRays(kHeight, kWidth, kDmin, kNumDisp, calibration_, X_WC_, options,
                            [&](int y, int x, float* c) {
                              const int pixel = y * kWidth + x;
                              if (!measured_[pixel]) return false;
                              std::copy(curves_[pixel].begin(), curves_[pixel].end(), c);
                              return true;
                            },
                            &grid);
    return grid;
  }

  OccupancyGrid Reference(const internal::RayIntegrationOptions& options) const {
    std::vector<std::vector<float>> curves = curves_;
    for (std::size_t i = 0; i < curves.size(); ++i) {
      if (!measured_[i]) std::fill(curves[i].begin(), curves[i].end(), 0.0f);
    }
    OccupancyGrid grid = MakeGrid();
    ReferenceIntegrate(curves, kWidth, kDmin, calibration_, X_WC_, options, &grid);
    return grid;
  }

  // fb = 40 * 0.3 = 12: depths from 12 / 32.5 = 0.37 m to 12 / 0.5 = 24 m; 10 cm cells are several disparity
  // steps thick near the camera and a small fraction of one far away.
  const StereoCalibration calibration_{40.0, 40.0, 23.5, 17.5, 0.3};
  std::vector<bool> measured_;
  std::vector<std::vector<float>> curves_;
  Eigen::Isometry3d X_WC_{Eigen::Isometry3d::Identity()};
};

// The fast update (fixed-point walk, tables, batches) against the model computed cell by cell in double precision.
// The two round differently (disparities to 2^-32 px, depths to about 2^-57 of the walk's length) so that the
// sample of a cell whose middle is within about 1e-9 px of a sample edge may differ; with these random rays no
// such tie occurs, and every cell is the same, bit for bit.
TEST_F(RayIntegrationTest, MatchesTheModelComputedCellByCell) {
  for (const double min_visibility : {0.25, 0.0}) {
    const internal::RayIntegrationOptions options{0.12, 0.97, min_visibility, 2};
    const OccupancyGrid fast = Integrate(options);
    const OccupancyGrid reference = Reference(options);
    int updated = 0;
    int differing = 0;
    for (std::size_t i = 0; i < fast.num_cells(); ++i) {
      updated += reference.log_odds(i) != 0.0f ? 1 : 0;
      differing += fast.log_odds(i) != reference.log_odds(i) ? 1 : 0;
    }
    EXPECT_GT(updated, 20000) << "min_visibility " << min_visibility;
    EXPECT_EQ(differing, 0) << "min_visibility " << min_visibility;
  }
}

// The accumulators are kept between calls (per calling thread) and must come back cleared, whatever the grid size
// and thread count of the previous call: results equal those of a thread that never ran an update.
TEST_F(RayIntegrationTest, KeptAccumulatorsDoNotLeakBetweenCalls) {
  const internal::RayIntegrationOptions options{0.12, 0.97, 0.25, 3};
  OccupancyGrid fresh = MakeGrid();
  std::thread([&] { fresh = Integrate(options); }).join();

  // Another frame: flat curves, which update other cells with other values.
  auto other_frame = [&](OccupancyGrid* grid, int threads) {
    internal::IntegrateRays(kHeight, kWidth, kDmin, kNumDisp, calibration_, X_WC_, {0.12, 0.97, 0.25, threads},
                            [&](int, int, float* c) {
                              std::fill(c, c + kNumDisp, 1.0f);
                              return true;
                            },
                            grid);
  };
  OccupancyGrid other = MakeGrid();
  OccupancyGrid small(Eigen::Vector3d(-1.0, -1.0, 0.0), 0.1, Eigen::Vector3i(20, 20, 40));
  other_frame(&other, 5);  // same grid size, more threads
  other_frame(&small, 2);  // another size
  other_frame(&other, 3);  // same size and threads as the frame under test
  const OccupancyGrid after_same = Integrate(options);
  other_frame(&small, 3);
  const OccupancyGrid after_resize = Integrate(options);
  int updated = 0;
  for (std::size_t i = 0; i < fresh.num_cells(); ++i) {
    updated += fresh.log_odds(i) != 0.0f ? 1 : 0;
    ASSERT_EQ(after_same.log_odds(i), fresh.log_odds(i)) << "cell " << i;
    ASSERT_EQ(after_resize.log_odds(i), fresh.log_odds(i)) << "cell " << i;
  }
  EXPECT_GT(updated, 20000);
}

}  // namespace
}  // namespace cairn::perception
