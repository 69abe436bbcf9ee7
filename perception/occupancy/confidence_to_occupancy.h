#pragma once

/// @file
/// ConfidenceToOccupancy: fuses per-frame whole-range stereo confidence into a 3-D occupancy grid.

#include <Eigen/Geometry>

#include "cairn/perception/occupancy/cost_curve_sensor_model.h"
#include "cairn/perception/occupancy/occupancy_grid.h"
#include "cairn/perception/stereo/disparity_volume.h"
#include "cairn/perception/stereo/stereo_calibration.h"
#include "cairn/systems/framework/leaf_system.h"

namespace cairn::perception {

/// Every `period` seconds (from t = `offset`), integrates the confidence volume on its input into the grid it holds
/// as state, through the cost-curve sensor model (thesis eqs. 4.13-4.17) at the camera pose on its other input.
/// ExecuteForcedEvents integrates the current frame at once: a diagram that must perceive before it plans (the
/// main diagram) forces the first frame after Simulator::Initialize and starts the periodic updates one period
/// later, so no frame is counted twice.
///
/// | port | type | meaning |
/// |---|---|---|
/// | input `confidence` | DisparityVolume | C(d) of the left image (StereoMatcher's `confidence`) |
/// | input `X_WC` | Eigen::Isometry3d | left camera pose in the grid's world frame |
/// | output `grid` | OccupancyGrid | the fused grid (the state) |
///
/// State: one abstract OccupancyGrid, initially the prototype given to the constructor, updated by a periodic
/// unrestricted update; the output depends on the state only, so the system breaks algebraic loops.
class ConfidenceToOccupancy final : public systems::LeafSystem {
 public:
  /// `prototype` fixes the grid's extent, resolution, clamps and initial values. Throws std::invalid_argument
  /// for a non-positive period, a negative offset or a bad calibration.
  ConfidenceToOccupancy(const OccupancyGrid& prototype, const StereoCalibration& calibration, double period,
                        const CostCurveSensorModel::Options& sensor_options = {}, double offset = 0.0);

  double period() const { return period_; }
  double offset() const { return offset_; }
  const StereoCalibration& calibration() const { return calibration_; }

  const systems::InputPort& get_confidence_input_port() const { return get_input_port(0); }
  const systems::InputPort& get_pose_input_port() const { return get_input_port(1); }
  const systems::OutputPort& get_grid_output_port() const { return get_output_port(0); }

 private:
  void Integrate(const systems::Context& context, systems::State* next) const;

  StereoCalibration calibration_;
  double period_;
  double offset_;
  CostCurveSensorModel model_;
  int grid_state_{};
};

}  // namespace cairn::perception
