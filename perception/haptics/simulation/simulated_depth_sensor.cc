#include "cairn/perception/haptics/simulation/simulated_depth_sensor.h"

#include <cmath>
#include <random>
#include <stdexcept>
#include <string>

#include "cairn/common/number_text.h"

namespace cairn::perception {

SimulatedDepthSensor::SimulatedDepthSensor() : SimulatedDepthSensor(Options{}) {}

SimulatedDepthSensor::SimulatedDepthSensor(const Options& options) : options_(options) {
  if (options.width < 1 || options.height < 1 ||
      static_cast<long long>(options.width) * options.height > kMaxPixels) {
    throw std::invalid_argument("the depth image is " + FormatShort(options.width) + " x " +
                                FormatShort(options.height) + "; both sides must be positive and the image at most " +
                                FormatShort(kMaxPixels) + " pixels");
  }
  for (const double fov : {options.horizontal_fov, options.vertical_fov}) {
    if (!(fov > 0.0) || !(fov < 3.0)) {
      throw std::invalid_argument("a field of view is " + FormatShort(fov) + " rad; it must lie in (0, 3)");
    }
  }
  if (!(options.min_range >= 0.0) || !(options.max_range > options.min_range) || !std::isfinite(options.max_range)) {
    throw std::invalid_argument("the range [" + FormatShort(options.min_range) + ", " +
                                FormatShort(options.max_range) + "] m must be finite with 0 <= min < max");
  }
  if (!(options.noise_coefficient >= 0.0) || !std::isfinite(options.noise_coefficient)) {
    throw std::invalid_argument("noise_coefficient is " + FormatShort(options.noise_coefficient) +
                                "; it must be non-negative and finite");
  }
}

Eigen::Isometry3d SimulatedDepthSensor::LookingAlong(const Eigen::Vector3d& position_W, double yaw) {
  const Eigen::Vector3d z(std::cos(yaw), std::sin(yaw), 0.0);
  const Eigen::Vector3d y(0.0, 0.0, -1.0);
  Eigen::Isometry3d X = Eigen::Isometry3d::Identity();
  X.linear().col(0) = y.cross(z);
  X.linear().col(1) = y;
  X.linear().col(2) = z;
  X.translation() = position_W;
  return X;
}

Eigen::Matrix3Xd SimulatedDepthSensor::Render(const std::vector<HapticSceneObject>& objects_W,
                                              const Eigen::Isometry3d& X_WC, std::uint64_t seed) const {
  const Options& o = options_;
  const double fx = 0.5 * o.width / std::tan(0.5 * o.horizontal_fov);
  const double fy = 0.5 * o.height / std::tan(0.5 * o.vertical_fov);
  const Eigen::Vector3d origin = X_WC.translation();
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> normal(0.0, 1.0);
  Eigen::Matrix3Xd points(3, static_cast<Eigen::Index>(o.width) * o.height);
  Eigen::Index n = 0;
  for (int v = 0; v < o.height; ++v) {
    for (int u = 0; u < o.width; ++u) {
      const Eigen::Vector3d ray_C((u + 0.5 - 0.5 * o.width) / fx, (v + 0.5 - 0.5 * o.height) / fy, 1.0);
      const Eigen::Vector3d dir_W = (X_WC.linear() * ray_C).normalized();
      const double ray_length_per_depth = ray_C.norm();  // t along the unit ray per metre of depth z
      double best = o.max_range * ray_length_per_depth;
      bool hit = false;
      for (const HapticSceneObject& object : objects_W) {
        const auto t = object.CastRay(origin, dir_W, best);
        if (t && *t < best) {
          best = *t;
          hit = true;
        }
      }
      if (o.render_ground && dir_W.z() < -1e-9) {
        const double t = -origin.z() / dir_W.z();
        if (t > 0.0 && t < best) {
          best = t;
          hit = true;
        }
      }
      // One draw per pixel whether or not it hits, so that the noise of a pixel does not depend on the others.
      const double noise = normal(rng);
      if (!hit) continue;
      const double depth = best / ray_length_per_depth;
      if (depth < o.min_range) continue;
      const double noisy = depth + o.noise_coefficient * depth * depth * noise;
      points.col(n++) = ray_C * noisy;
    }
  }
  return points.leftCols(n);
}

}  // namespace cairn::perception
