#include "cairn/perception/haptics/simulation/simulated_depth_camera.h"

#include <cmath>
#include <stdexcept>
#include <utility>

#include "cairn/common/number_text.h"
#include "cairn/systems/framework/state.h"

namespace cairn::perception {

SimulatedDepthCamera::SimulatedDepthCamera(const SimulatedDepthSensor::Options& sensor,
                                           std::vector<HapticSceneObject> objects_W, double period,
                                           std::uint64_t seed)
    : sensor_(sensor), objects_W_(std::move(objects_W)), seed_(seed) {
  if (!(period > 0.0) || !std::isfinite(period)) {
    throw std::invalid_argument("SimulatedDepthCamera: period " + FormatShort(period) +
                                " s must be positive and finite (e.g. 0.5)");
  }
  DeclareAbstractInputPort("X_WC", systems::Value<Eigen::Isometry3d>(Eigen::Isometry3d::Identity()));
  frame_state_ = DeclareAbstractState(systems::Value<Eigen::Matrix3Xd>(Eigen::Matrix3Xd(3, 0)));
  count_state_ = DeclareAbstractState(systems::Value<int>(0));
  const int frame = frame_state_;
  DeclareAbstractOutputPort(
      "points_C", systems::Value<Eigen::Matrix3Xd>(Eigen::Matrix3Xd(3, 0)),
      [frame](const systems::Context& c, systems::AbstractValue* v) { v->SetFrom(c.get_abstract_state_value(frame)); },
      {abstract_state_ticket(frame)});
  DeclarePeriodicUnrestrictedUpdateEvent(period, 0.0, &SimulatedDepthCamera::Render);
}

void SimulatedDepthCamera::Render(const systems::Context& context, systems::State* next) const {
  int& count = next->get_mutable_abstract_state<int>(count_state_);
  next->get_mutable_abstract_state<Eigen::Matrix3Xd>(frame_state_) =
      sensor_.Render(objects_W_, get_pose_input_port().Eval<Eigen::Isometry3d>(context),
                     seed_ * 0x9E3779B97F4A7C15ULL + static_cast<std::uint64_t>(count));
  ++count;
}

}  // namespace cairn::perception
