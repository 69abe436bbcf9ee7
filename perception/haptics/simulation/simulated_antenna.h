#pragma once

/// @file
/// The pan-tilt-telescopic antenna of the haptic-affordance simulation (seed 000, §2, Fig. 8).

#include <optional>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "cairn/perception/haptics/simulation/haptic_scene_object.h"

namespace cairn::perception {

/// What one haptic interaction found.
struct AntennaInteraction {
  /// The tip met a stiff element: the object is non-traversable (§3.6).
  bool blocked{false};
  /// Targets reached before the end or the block.
  int targets_reached{0};
  /// Targets out of the antenna's workspace, skipped.
  int targets_unreachable{0};
  /// Where the tip stopped (W).
  Eigen::Vector3d tip_W{Eigen::Vector3d::Zero()};
  /// Length of the tip's path (m).
  double path_length{0.0};
};

/// A pan-tilt-telescopic antenna (data/robots/cairn_antenna.urdf: pan about y_A, tilt about x_A, extension along
/// the rotated z_A). Its frame A follows the sensor's convention (x right, y down, z forward), so the tip is at
///   p_A = L (cos t sin p, -sin t, cos t cos p)
/// for pan p, tilt t (positive up) and extension L, and the inverse kinematics is the cartesian-to-polar map of
/// §3.2. An interaction (Fig. 8) stretches the antenna to the distance of the furthest target along the first
/// target's direction, then moves through the targets in order, interpolating the joints; the tip (a ball) is
/// checked against the objects every `step` metres of tip motion and stops at the first stiff element it
/// touches. Soft elements bend out of its way.
class SimulatedAntenna {
 public:
  struct Options {
    double min_pan{-1.5707963267948966};
    double max_pan{1.5707963267948966};
    double min_tilt{-1.5707963267948966};
    double max_tilt{1.5707963267948966};
    /// The telescope's travel (m): 1 m stretched, as on the paper's robot.
    double min_extension{0.05};
    double max_extension{1.0};
    double tip_radius{0.01};
    /// Largest tip motion between collision checks (m).
    double step{0.005};
  };

  /// Most targets an interaction follows.
  static constexpr int kMaxTargets = 10000;

  /// Throws std::invalid_argument naming the first invalid option.
  explicit SimulatedAntenna(const Options& options);
  /// The default options.
  SimulatedAntenna();

  /// The tip in A for joints q = (pan, tilt, extension).
  static Eigen::Vector3d TipPosition(const Eigen::Vector3d& q);
  /// The joints reaching p_A, or nothing outside the joint limits.
  std::optional<Eigen::Vector3d> InverseKinematics(const Eigen::Vector3d& p_A) const;

  /// Runs one interaction through `targets_A` with the antenna base at X_WA. Throws std::invalid_argument for more
  /// than kMaxTargets targets or a non-finite one.
  AntennaInteraction Probe(const std::vector<Eigen::Vector3d>& targets_A,
                           const std::vector<HapticSceneObject>& objects_W, const Eigen::Isometry3d& X_WA) const;

  const Options& options() const { return options_; }

 private:
  Options options_;
};

}  // namespace cairn::perception
