#pragma once

/// @file
/// SimulatedDepthCamera: the ray-cast depth sensor as a block-diagram system.

#include <cstdint>
#include <vector>

#include <Eigen/Geometry>

#include "cairn/perception/haptics/simulation/haptic_scene_object.h"
#include "cairn/perception/haptics/simulation/simulated_depth_sensor.h"
#include "cairn/systems/framework/leaf_system.h"

namespace cairn::perception {

/// Every `period` seconds renders the objects from the pose on its input and holds the frame as state.
///
/// | port | type | meaning |
/// |---|---|---|
/// | input `X_WC` | Eigen::Isometry3d | the sensor's pose |
/// | output `points_C` | Eigen::Matrix3Xd | the last frame's points in the sensor frame (state) |
///
/// State: the last frame (abstract, empty before the first update) and the frame count (abstract int), which
/// seeds each frame's noise with `seed` so that a run is reproducible.
class SimulatedDepthCamera final : public systems::LeafSystem {
 public:
  /// Throws std::invalid_argument for invalid sensor options or a non-positive period.
  SimulatedDepthCamera(const SimulatedDepthSensor::Options& sensor, std::vector<HapticSceneObject> objects_W,
                       double period, std::uint64_t seed);

  const systems::InputPort& get_pose_input_port() const { return get_input_port(0); }
  const systems::OutputPort& get_points_output_port() const { return get_output_port(0); }

 private:
  void Render(const systems::Context& context, systems::State* next) const;

  SimulatedDepthSensor sensor_;
  std::vector<HapticSceneObject> objects_W_;
  std::uint64_t seed_;
  int frame_state_{};
  int count_state_{};
};

}  // namespace cairn::perception
