#pragma once

/// @file
/// A ray-cast structured-light depth sensor for the haptic-affordance simulation (seed 000).

#include <cstdint>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "cairn/perception/haptics/simulation/haptic_scene_object.h"

namespace cairn::perception {

/// A pinhole depth camera (the paper's Kinect, at reduced resolution) that casts one ray per pixel into the
/// objects (and optionally the ground plane z = 0) and returns the hit points in its frame C (x right, y down,
/// z along the optical axis). Structured-light depth noise grows with the square of the range: each depth is
/// perturbed by a zero-mean Gaussian of standard deviation noise_coefficient z² (Khoshelham and Elberink's
/// Kinect model, 1.425e-3 m⁻¹), drawn from a std::mt19937_64 seeded per frame. Pixels nearer than min_range
/// or beyond max_range give no point, as with the real sensor.
class SimulatedDepthSensor {
 public:
  struct Options {
    int width{200};
    int height{150};
    /// Horizontal and vertical fields of view (rad): the Kinect's 57° x 43°.
    double horizontal_fov{0.9948};
    double vertical_fov{0.7505};
    double min_range{0.4};
    double max_range{4.0};
    double noise_coefficient{1.425e-3};
    bool render_ground{false};
  };

  /// Most pixels.
  static constexpr int kMaxPixels = 1 << 22;

  /// Throws std::invalid_argument naming the first invalid option.
  explicit SimulatedDepthSensor(const Options& options);
  /// The default options.
  SimulatedDepthSensor();

  /// The pose X_WC of a sensor at `position_W` looking horizontally along heading `yaw` (rad, about z_W from x_W):
  /// z_C = (cos yaw, sin yaw, 0), y_C = -z_W (down), x_C = y_C x z_C (right).
  static Eigen::Isometry3d LookingAlong(const Eigen::Vector3d& position_W, double yaw);

  /// The points seen from X_WC, in C, in row-major pixel order.
  Eigen::Matrix3Xd Render(const std::vector<HapticSceneObject>& objects_W, const Eigen::Isometry3d& X_WC,
                          std::uint64_t seed) const;

  const Options& options() const { return options_; }

 private:
  Options options_;
};

}  // namespace cairn::perception
