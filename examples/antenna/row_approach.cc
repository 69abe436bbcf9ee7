#include "examples/antenna/row_approach.h"

#include <cmath>
#include <stdexcept>

#include "cairn/common/number_text.h"
#include "cairn/perception/haptics/simulation/simulated_depth_sensor.h"

namespace cairn::examples {

RowApproach::RowApproach(int objects, int frames_per_object, double spacing, double sensor_height, double period)
    : objects_(objects), frames_per_object_(frames_per_object), spacing_(spacing), sensor_height_(sensor_height),
      period_(period) {
  if (objects < 1 || frames_per_object < 1) {
    throw std::invalid_argument("RowApproach: " + FormatShort(objects) + " objects and " +
                                FormatShort(frames_per_object) + " frames per object; both must be at least 1");
  }
  if (!(spacing > 0.0) || !(sensor_height > 0.0) || !(period > 0.0) || !std::isfinite(spacing) ||
      !std::isfinite(sensor_height) || !std::isfinite(period)) {
    throw std::invalid_argument("RowApproach: spacing " + FormatShort(spacing) + " m, sensor height " +
                                FormatShort(sensor_height) + " m and period " + FormatShort(period) +
                                " s must be positive and finite");
  }
  DeclareAbstractOutputPort("X_WC", systems::Value<Eigen::Isometry3d>(Eigen::Isometry3d::Identity()),
                            [this](const systems::Context& c, systems::AbstractValue* v) {
                              v->get_mutable_value<Eigen::Isometry3d>() = PoseAt(c.get_time());
                            },
                            {time_ticket()});
}

int RowApproach::ObjectAt(double t) const {
  const long long frame = static_cast<long long>(std::floor(t / period_ + 1e-9));
  return static_cast<int>((frame / frames_per_object_) % objects_);
}

Eigen::Isometry3d RowApproach::PoseAt(double t) const {
  const long long frame = static_cast<long long>(std::floor(t / period_ + 1e-9));
  const int object = ObjectAt(t);
  const double j = static_cast<double>(frame % frames_per_object_);
  const double heading = 0.5 * std::sin(1.7 * j + object);
  const double distance = 0.7 + 0.1 * std::cos(2.3 * j + object);
  const Eigen::Vector3d position(object * spacing_ - distance * std::cos(heading), -distance * std::sin(heading),
                                 sensor_height_);
  return perception::SimulatedDepthSensor::LookingAlong(position, heading);
}

}  // namespace cairn::examples
