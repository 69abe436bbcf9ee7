#include "cairn/perception/occupancy/cost_curve_sensor_model.h"

#include <cmath>
#include <random>
#include <stdexcept>
#include <vector>

#include "cairn/perception/occupancy/wta_range_sensor_model.h"
#include "cairn/perception/stereo/winner_take_all.h"
#include "expect_throws.h"

namespace cairn::perception {
namespace {

// One pixel looking down +x of the world; the grid's cells are one disparity step... checked analytically.
TEST(CostCurveSensorModelTest, SinglePixelFollowsTheClosedForm) {
  // fx * baseline = 10; disparities 1..10 map to depths 10 / d. A 1 x 1 image with the principal point at the
  // pixel, camera at the origin looking along world +z.
  const StereoCalibration calibration{1.0, 1.0, 0.0, 0.0, 10.0};
  DisparityVolume confidence(1, 1, 1, 10);
  float* c = confidence.mutable_curve(0, 0);
  for (int k = 0; k < 10; ++k) c[k] = 0.0f;
  c[4] = 0.8f;  // d = 5: depth 2
  c[1] = 0.2f;  // d = 2: depth 5
  // Cells of 0.1 m along z from 1 to 7 m.
  OccupancyGrid grid(Eigen::Vector3d(-0.05, -0.05, 1.0), 0.1, Eigen::Vector3i(1, 1, 60));
  CostCurveSensorModel::Options options;
  options.min_visibility = 0.0;
  CostCurveSensorModel(options).Integrate(confidence, calibration, Eigen::Isometry3d::Identity(), &grid);
  auto p_at = [&](double z) { return grid.Probability(Eigen::Vector3d(0.0, 0.0, z)); };
  // In front of the first peak: free (clamped at 0.12). Within the d = 5 sample: 0.8 + 0.5 * 0 -> 0.8.
  EXPECT_NEAR(p_at(1.55), 0.12, 1e-4);
  EXPECT_NEAR(p_at(2.0), 0.8, 1e-4);
  // Between the peaks: mass 0, front 0.8 -> 0.4. At the second peak: 0.2 + 0.5 * 0.8 = 0.6.
  EXPECT_NEAR(p_at(3.0), 0.4, 1e-4);
  EXPECT_NEAR(p_at(5.0), 0.6, 1e-4);
}

// The grid must not depend on how the rows are split across threads (the per-thread sums are integers).
TEST(CostCurveSensorModelTest, SameGridForAnyThreadCount) {
  const StereoCalibration calibration{40.0, 40.0, 15.5, 11.5, 0.2};
  DisparityVolume confidence(24, 32, 1, 16);
  std::mt19937 rng(5);
  std::exponential_distribution<float> mass(1.0f);
  for (int y = 0; y < 24; ++y)
    for (int x = 0; x < 32; ++x) {
      float* c = confidence.mutable_curve(y, x);
      float sum = 0.0f;
      for (int k = 0; k < 16; ++k) sum += (c[k] = mass(rng) * mass(rng));
      for (int k = 0; k < 16; ++k) c[k] /= sum;
    }
  std::vector<float> reference;
  for (int threads : {1, 2, 3, 7}) {
    OccupancyGrid grid(Eigen::Vector3d(-4.0, -3.0, 0.0), 0.1, Eigen::Vector3i(80, 60, 90));
    CostCurveSensorModel::Options options;
    options.num_threads = threads;
    const Eigen::Isometry3d X_WC(Eigen::AngleAxisd(0.2, Eigen::Vector3d::UnitY()));
    CostCurveSensorModel(options).Integrate(confidence, calibration, X_WC, &grid);
    std::vector<float> log_odds(grid.num_cells());
    int updated = 0;
    for (std::size_t i = 0; i < grid.num_cells(); ++i) {
      log_odds[i] = grid.log_odds(i);
      updated += log_odds[i] != 0.0f ? 1 : 0;
    }
    EXPECT_GT(updated, 1000);
    if (reference.empty()) {
      reference = log_odds;
    } else {
      EXPECT_TRUE(log_odds == reference) << threads << " threads";
    }
  }
}

TEST(CostCurveSensorModelTest, RejectsBadInput) {
  CostCurveSensorModel::Options options;
  options.max_probability = 0.4;
  CAIRN_EXPECT_THROWS_WITH(CostCurveSensorModel{options}, std::invalid_argument, "0 < min < 0.5 < max < 1");
  OccupancyGrid grid(Eigen::Vector3d::Zero(), 0.1, Eigen::Vector3i(2, 2, 2));
  DisparityVolume zero_start(2, 2, 0, 5);
  CAIRN_EXPECT_THROWS_WITH(
      CostCurveSensorModel().Integrate(zero_start, StereoCalibration{}, Eigen::Isometry3d::Identity(), &grid),
      std::invalid_argument, "min disparity 0", "from disparity 1");
  StereoCalibration bad;
  bad.baseline = 0.0;
  CAIRN_EXPECT_THROWS_WITH(
      CostCurveSensorModel().Integrate(DisparityVolume(2, 2, 1, 5), bad, Eigen::Isometry3d::Identity(), &grid),
      std::invalid_argument, "baseline");
  options = CostCurveSensorModel::Options{};
  options.min_probability = 1e-30;
  CAIRN_EXPECT_THROWS_WITH(CostCurveSensorModel(options).Integrate(DisparityVolume(2, 2, 1, 5), StereoCalibration{},
                                                                  Eigen::Isometry3d::Identity(), &grid),
                           std::invalid_argument, "too close to 0 or 1");
  options.min_probability = 0.12;
  options.max_probability = 0.99999999;  // a valid double, but 1.0f in the update's float arithmetic
  CAIRN_EXPECT_THROWS_WITH(CostCurveSensorModel(options).Integrate(DisparityVolume(2, 2, 1, 5), StereoCalibration{},
                                                                  Eigen::Isometry3d::Identity(), &grid),
                           std::invalid_argument, "too close to 0 or 1");
  // A WTA result's disparity range sizes the update's scratch: wider than the image is refused before any work.
  WtaResult wta;
  ComputeWinnerTakeAll(DisparityVolume(4, 8, 1, 5), WtaOptions{}, &wta);
  const WtaRangeSensorModel wta_model(WtaRangeSensorModel::Options{});
  CAIRN_EXPECT_THROWS_WITH(
      wta_model.Integrate(wta, 1, 1 << 20, StereoCalibration{}, Eigen::Isometry3d::Identity(), &grid),
      std::invalid_argument, "max disparity 1048576 is not below the image width 8");
}

}  // namespace
}  // namespace cairn::perception
