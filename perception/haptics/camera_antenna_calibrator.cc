#include "cairn/perception/haptics/camera_antenna_calibrator.h"

#include <stdexcept>
#include <string>

#include "cairn/common/number_text.h"
#include "cairn/perception/haptics/point_cloud_reduction.h"

namespace cairn::perception {
namespace {

std::string Describe(const Eigen::Vector3d& p) {
  return "(" + FormatShort(p.x()) + ", " + FormatShort(p.y()) + ", " + FormatShort(p.z()) + ")";
}

const CameraAntennaCalibrator::Options& Checked(const CameraAntennaCalibrator::Options& options) {
  if (options.min_inliers < 4) {
    throw std::invalid_argument("min_inliers is " + FormatShort(options.min_inliers) +
                                "; a sphere needs at least 4 points");
  }
  return options;
}

}  // namespace

Eigen::Matrix3Xd CameraAntennaCalibrator::Table1Points() {
  Eigen::Matrix3Xd points(3, 5);
  points << -0.3, -0.3, 0.0, 0.1, -0.2,  //
      0.1, 0.2, 0.0, 0.1, 0.1,           //
      0.6, 0.6, 0.8, 0.8, 0.8;
  return points;
}

CameraAntennaCalibrator::CameraAntennaCalibrator(const Eigen::Matrix3Xd& reference_C)
    : CameraAntennaCalibrator(reference_C, Options{}) {}

CameraAntennaCalibrator::CameraAntennaCalibrator(const Eigen::Matrix3Xd& reference_C, const Options& options)
    : options_(Checked(options)),
      background_(KeepWithinReach(reference_C, options.reach_center_C, options.reach_radius),
                  options.background_resolution),
      ransac_(options.ransac) {}

const CameraAntennaCalibrator::Observation& CameraAntennaCalibrator::AddObservation(const Eigen::Vector3d& p_A,
                                                                                    const Eigen::Matrix3Xd& cloud_C) {
  if (static_cast<int>(observations_.size()) >= kMaxObservations) {
    throw std::length_error("the calibration already holds " + FormatShort(kMaxObservations) +
                            " observations, its limit");
  }
  if (!p_A.allFinite()) throw std::invalid_argument("the commanded tip position " + Describe(p_A) + " is not finite");
  const Eigen::Matrix3Xd foreground =
      background_.Foreground(KeepWithinReach(cloud_C, options_.reach_center_C, options_.reach_radius));
  if (foreground.cols() < 4) {
    throw std::runtime_error("the tip commanded to " + Describe(p_A) + " left only " +
                             FormatShort(static_cast<long long>(foreground.cols())) +
                             " foreground points; is the tip in the sensor's view?");
  }
  Observation observation;
  observation.p_A = p_A;
  observation.foreground_points = static_cast<int>(foreground.cols());
  try {
    observation.sphere = ransac_.Fit(foreground);
  } catch (const std::runtime_error& error) {
    throw std::runtime_error("the tip commanded to " + Describe(p_A) + ": " + error.what());
  }
  if (static_cast<int>(observation.sphere.inliers.size()) < options_.min_inliers) {
    throw std::runtime_error("the tip commanded to " + Describe(p_A) + " fitted a sphere with only " +
                             FormatShort(static_cast<long long>(observation.sphere.inliers.size())) +
                             " inliers; at least " + FormatShort(options_.min_inliers) + " are required");
  }
  observation.p_C = options_.use_sphere_center ? observation.sphere.center : observation.sphere.inlier_centroid;
  observations_.push_back(std::move(observation));
  return observations_.back();
}

RigidTransformFit CameraAntennaCalibrator::Solve() const {
  Eigen::Matrix3Xd p_C(3, static_cast<Eigen::Index>(observations_.size()));
  Eigen::Matrix3Xd p_A(3, static_cast<Eigen::Index>(observations_.size()));
  for (std::size_t i = 0; i < observations_.size(); ++i) {
    p_C.col(static_cast<Eigen::Index>(i)) = observations_[i].p_C;
    p_A.col(static_cast<Eigen::Index>(i)) = observations_[i].p_A;
  }
  return FitRigidTransform(p_C, p_A);
}

}  // namespace cairn::perception
