#include "cairn/perception/occupancy/cost_curve_sensor_model.h"

#include <cmath>
#include <stdexcept>

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
}

}  // namespace
}  // namespace cairn::perception
