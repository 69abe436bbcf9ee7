#include "cairn/common/number_text.h"
#include "cairn/perception/occupancy/confidence_to_occupancy.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include "cairn/systems/framework/state.h"

namespace cairn::perception {

ConfidenceToOccupancy::ConfidenceToOccupancy(const OccupancyGrid& prototype, const StereoCalibration& calibration,
                                             double period, const CostCurveSensorModel::Options& sensor_options,
                                             double offset)
    : calibration_(calibration), period_(period), offset_(offset), model_(sensor_options) {
  if (!(period > 0.0) || !std::isfinite(period)) {
    throw std::invalid_argument("ConfidenceToOccupancy: period " + cairn::FormatShort(period) +
                                " s must be positive and finite (the camera's frame period, e.g. 0.1)");
  }
  if (!(offset >= 0.0) || !std::isfinite(offset)) {
    throw std::invalid_argument("ConfidenceToOccupancy: offset " + cairn::FormatShort(offset) +
                                " s must be finite and >= 0 (the time of the first periodic update)");
  }
  calibration.Validate();
  DeclareAbstractInputPort("confidence", systems::Value<DisparityVolume>(DisparityVolume()));
  DeclareAbstractInputPort("X_WC", systems::Value<Eigen::Isometry3d>(Eigen::Isometry3d::Identity()));
  grid_state_ = DeclareAbstractState(systems::Value<OccupancyGrid>(prototype));
  const int grid = grid_state_;
  DeclareAbstractOutputPort(
      "grid", systems::Value<OccupancyGrid>(prototype),
      [grid](const systems::Context& c, systems::AbstractValue* v) { v->SetFrom(c.get_abstract_state_value(grid)); },
      {abstract_state_ticket(grid)});
  DeclarePeriodicUnrestrictedUpdateEvent(period, offset, &ConfidenceToOccupancy::Integrate);
  DeclareForcedUnrestrictedUpdateEvent(&ConfidenceToOccupancy::Integrate);
}

void ConfidenceToOccupancy::Integrate(const systems::Context& context, systems::State* next) const {
  const auto& confidence = get_confidence_input_port().Eval<DisparityVolume>(context);
  const auto& X_WC = get_pose_input_port().Eval<Eigen::Isometry3d>(context);
  model_.Integrate(confidence, calibration_, X_WC, &next->get_mutable_abstract_state<OccupancyGrid>(grid_state_));
}

}  // namespace cairn::perception
