#pragma once

/// @file
/// RANSAC fitting of a sphere, to find the antenna's spherical tip in a foreground cloud (seed 000, §3.2).

#include <cstdint>
#include <vector>

#include <Eigen/Core>

namespace cairn::perception {

/// A fitted sphere and the points it explains.
struct SphereFit {
  Eigen::Vector3d center{Eigen::Vector3d::Zero()};
  double radius{0.0};
  /// Indices (cloud columns) of the inliers, ascending.
  std::vector<int> inliers;
  /// The centroid of the inliers: the paper's estimate of the tip position (only the side facing the sensor is
  /// seen, so it lies up to r/2 in front of the centre).
  Eigen::Vector3d inlier_centroid{Eigen::Vector3d::Zero()};
  /// RANSAC hypotheses drawn.
  int iterations{0};
};

/// RANSAC (Fischler and Bolles) over spheres through four sampled points; the hypothesis with the most inliers
/// (points within inlier_threshold of the surface) wins, ties keeping the earlier one, and the sphere is then
/// refitted to its inliers by linear least squares. The sampler is a std::mt19937_64 seeded by `seed`, whose
/// sequence the C++ standard fixes, and indices are drawn by modulo so that the result is the same with any
/// standard library.
class SphereRansac {
 public:
  struct Options {
    /// Hypotheses drawn.
    int iterations{500};
    /// Inlier distance from the surface (m).
    double inlier_threshold{0.003};
    /// Hypotheses with a radius outside [min_radius, max_radius] are rejected (m).
    double min_radius{0.005};
    double max_radius{0.1};
    std::uint64_t seed{0};
  };

  /// Most hypotheses.
  static constexpr int kMaxIterations = 1000000;

  /// Throws std::invalid_argument naming the first invalid option.
  explicit SphereRansac(const Options& options);
  /// The default options.
  SphereRansac();

  /// The best sphere. Throws std::invalid_argument for fewer than 4 points or more than kMaxHapticCloudPoints, and
  /// std::runtime_error when no hypothesis within the radius bounds was found (saying how many were tried).
  SphereFit Fit(const Eigen::Matrix3Xd& points) const;

  /// The sphere through four points (centre, radius), or false when they are (nearly) coplanar.
  static bool SphereThrough(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c,
                            const Eigen::Vector3d& d, Eigen::Vector3d* center, double* radius);

  const Options& options() const { return options_; }

 private:
  Options options_;
};

}  // namespace cairn::perception
