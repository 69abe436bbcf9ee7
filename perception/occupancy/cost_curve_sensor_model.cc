#include "cairn/perception/occupancy/cost_curve_sensor_model.h"

#include <stdexcept>
#include <string>

#include "cairn/common/cairn_assert.h"
#include "cairn/perception/occupancy/internal/ray_integration.h"

namespace cairn::perception {

CostCurveSensorModel::CostCurveSensorModel() : CostCurveSensorModel(Options{}) {}

CostCurveSensorModel::CostCurveSensorModel(const Options& options) : options_(options) {
  if (!(options.min_probability > 0.0 && options.min_probability < 0.5 && options.max_probability > 0.5 &&
        options.max_probability < 1.0)) {
    throw std::invalid_argument("sensor-model probability limits [" + std::to_string(options.min_probability) +
                                ", " + std::to_string(options.max_probability) +
                                "] must satisfy 0 < min < 0.5 < max < 1, e.g. [0.12, 0.97]");
  }
}

void CostCurveSensorModel::Integrate(const DisparityVolume& confidence, const StereoCalibration& calibration,
                                     const Eigen::Isometry3d& X_WC, OccupancyGrid* grid) const {
  CAIRN_CHECK(grid != nullptr);
  calibration.Validate();
  if (confidence.num_disparities() == 0) {
    throw std::invalid_argument("CostCurveSensorModel: the confidence volume is empty; run ComputeConfidence() first");
  }
  if (confidence.min_disparity() < 1) {
    throw std::invalid_argument("CostCurveSensorModel: min disparity " + std::to_string(confidence.min_disparity()) +
                                " puts the ray's far end at infinity; match from disparity 1 or more");
  }
  const int num_disp = confidence.num_disparities();
  internal::IntegrateRays(confidence.height(), confidence.width(), confidence.min_disparity(), num_disp, calibration,
                          X_WC, {options_.min_probability, options_.max_probability, options_.min_visibility, options_.num_threads},
                          [&](int y, int x, float* c) {
                            const float* source = confidence.curve(y, x);
                            std::copy(source, source + num_disp, c);
                            return true;
                          },
                          grid);
}

}  // namespace cairn::perception
