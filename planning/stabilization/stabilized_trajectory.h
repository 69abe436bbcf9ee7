#pragma once

#include <string>
#include <vector>

#include <Eigen/Core>

namespace cairn::planning {

/// How stabilisation went, per trajectory (thesis 2.5.1c): the ZMP of the motion from the full multibody model
/// against the reference ZMP (the interpolated COM projection of the optimiser), before and after.
struct StabilizationReport {
  bool success{false};          ///< a reference was produced (also when the error did not fall below tolerance)
  std::string method;           ///< "fft", "preview" or "none"
  std::string message;          ///< one line: what happened, or why there is no reference
  double rms_error_before{0.0}; ///< RMS over samples of |zmp - zmp_ref| (horizontal), m, of the interpolated motion
  double max_error_before{0.0}; ///< its maximum, m
  double rms_error_after{0.0};  ///< the same for the stabilised motion, m
  double max_error_after{0.0};
  /// Smallest signed distance of the ZMP to its support polygon's edge over the samples (positive inside), m.
  double min_support_margin_before{0.0};
  double min_support_margin_after{0.0};
  /// Samples whose motion needs no support force or a pulling one (f_z <= 0: no ZMP; left out of the errors).
  int unsupported_samples_before{0};
  int unsupported_samples_after{0};
  int iterations{0};            ///< compensation passes kept
  bool joint_limits_held{false};  ///< every sample within the model's position limits
  /// Largest error of the leg inverse kinematics (sole position) over the samples, m.
  double max_ik_error{0.0};
  double seconds{0.0};          ///< wall time (not part of any decision)
};

/// The dense reference for the plant: q and v at the control rate, the reference ZMP and the motion's ZMP.
struct StabilizedTrajectory {
  double period{0.0};                    ///< s between samples (sample k is at k * period)
  std::vector<Eigen::VectorXd> q;        ///< configurations (floating base [x y z qw qx qy qz] first)
  std::vector<Eigen::VectorXd> v;        ///< velocities (floating base body twist [w; v] first)
  std::vector<Eigen::Vector2d> zmp_reference;  ///< interpolated COM projection of the optimiser's waypoints
  std::vector<Eigen::Vector2d> zmp;      ///< ZMP of the stabilised motion from the full model
  std::vector<Eigen::Vector2d> zmp_before;  ///< ZMP of the interpolated (unstabilised) motion
  std::vector<Eigen::Vector2d> com;      ///< horizontal COM of the stabilised motion
  /// Which soles carry weight at each sample (from the plan's timing): bit 0 left, bit 1 right.
  std::vector<int> contacts;
  StabilizationReport report;

  /// Duration, s (0 when empty).
  double duration() const { return q.empty() ? 0.0 : period * static_cast<double>(q.size() - 1); }
  /// The sample nearest to t (clamped to the ends); throws std::out_of_range when empty.
  std::size_t SampleAt(double t) const;
};

}  // namespace cairn::planning
