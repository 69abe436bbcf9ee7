#pragma once

/// @file
/// Camera–antenna calibration by babbling (seed 000, §3.2).

#include <vector>

#include <Eigen/Core>

#include "cairn/perception/haptics/background_subtractor.h"
#include "cairn/perception/haptics/rigid_transform_fit.h"
#include "cairn/perception/haptics/sphere_ransac.h"

namespace cairn::perception {

/// Learns M = X_AC (p_A = M p_C, eq. 3) from a babbling behaviour: with the antenna retracted a reference cloud
/// is taken; then for each commanded tip position p_A the new cloud's foreground (cells the reference left
/// empty) is fitted with a RANSAC sphere, and the centroid of its inliers is the tip seen in C. The rigid fit of
/// eq. 5 over all correspondences gives M and its residual.
class CameraAntennaCalibrator {
 public:
  struct Options {
    /// Cell side of the background subtraction (m).
    double background_resolution{0.01};
    /// Only points within reach_radius of reach_center_C take part (the paper's "within the antenna's reach").
    Eigen::Vector3d reach_center_C{Eigen::Vector3d::Zero()};
    double reach_radius{1.5};
    SphereRansac::Options ransac{};
    /// Fewest inliers for an observation to count.
    int min_inliers{8};
    /// Use the fitted sphere's centre instead of the paper's inlier centroid (which lies in front of the centre,
    /// towards the sensor, by up to half the radius).
    bool use_sphere_center{false};
  };

  /// One babbling pose.
  struct Observation {
    Eigen::Vector3d p_A{Eigen::Vector3d::Zero()};
    Eigen::Vector3d p_C{Eigen::Vector3d::Zero()};
    SphereFit sphere;
    /// Foreground points the sphere was fitted to.
    int foreground_points{0};
  };

  /// Most babbling poses.
  static constexpr int kMaxObservations = 10000;

  /// The five tip positions of Table 1, in the antenna frame (m).
  static Eigen::Matrix3Xd Table1Points();

  /// Throws std::invalid_argument for invalid options or a reference cloud the reductions refuse.
  CameraAntennaCalibrator(const Eigen::Matrix3Xd& reference_C, const Options& options);
  /// The default options.
  explicit CameraAntennaCalibrator(const Eigen::Matrix3Xd& reference_C);

  /// Segments and fits the tip in `cloud_C` taken with the tip commanded to `p_A`, and records the correspondence.
  /// Throws std::runtime_error (naming the pose) when the foreground has fewer than 4 points, no sphere fits, or
  /// the sphere has fewer than min_inliers inliers; std::length_error beyond kMaxObservations.
  const Observation& AddObservation(const Eigen::Vector3d& p_A, const Eigen::Matrix3Xd& cloud_C);

  /// The rigid fit over the observations. Throws std::invalid_argument with fewer than 3 (or degenerate) ones.
  RigidTransformFit Solve() const;

  const std::vector<Observation>& observations() const { return observations_; }

 private:
  Options options_;
  BackgroundSubtractor background_;
  SphereRansac ransac_;
  std::vector<Observation> observations_;
};

}  // namespace cairn::perception
