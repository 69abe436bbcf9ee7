#pragma once

/// @file
/// ProbeArmPlant: seed 001's terrain probe simulated in the physics plant — a yaw-pitch arm with a push rod and a
/// force-sensing tip (data/robots/cairn_probe_arm.urdf) pushing a set depth into a terrain box of given stiffness.

#include <random>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "cairn/multibody/model.h"

namespace cairn::planning {

/// One probe, simulated: the arm's base is welded at the robot's base (the robot stands still while probing), the
/// arm is placed with its rod pointing at the target from `clearance` m above the ground, then its yaw, pitch and
/// push joints are driven under joint PD (with gravity compensation) while the push reference ramps over
/// `push_time` to the extension that puts the tip `depth` m below the surface, and is held for `hold_time`. During
/// the hold, `samples` force readings are taken at equal intervals: the normal force of the tip's contacts with the
/// terrain (multibody::BulletPlant, whose terrain box yields with its contact stiffness and damping) plus seeded
/// Gaussian sensor noise. The ground under the target is one box of side `patch_size` (containing the target) with
/// its top at the ground height; ground without support within the probe's reach (deep water) has no box, so the
/// tip meets nothing.
/// Against a box of stiffness k the settled reading is k times the depth reached, which the stiff push drive keeps
/// within a few percent of `depth` (the drive and the ground act as springs in series).
class ProbeArmPlant {
 public:
  struct Options {
    /// Height of the arm's base (the yaw and pitch axes) above the ground at the robot, m.
    double mount_height{0.5};
    /// Distance of the tip's surface above the ground, along the rod, when the push starts, m.
    double clearance{0.03};
    /// Depth below the ground surface the tip is driven to, m.
    double depth{0.02};
    double push_time{0.15};
    double hold_time{0.1};
    /// Force readings during the hold.
    int samples{20};
    /// Standard deviation of the force sensor's Gaussian noise, N.
    double noise{2.0};
    /// Plant step, s.
    double time_step{5e-4};
    /// PD gains of yaw and pitch (N m/rad, N m s/rad) and of the push joint (N/m, N s/m).
    double kp_rotary{1e5};
    double kd_rotary{400.0};
    double kp_push{2e5};
    double kd_push{800.0};
    /// Side of the square ground patch under the target, m.
    double patch_size{0.2};
  };

  /// The ground under the target.
  struct Ground {
    /// Height of the surface, m.
    double height{0.0};
    /// Contact stiffness, N/m: 0 is no support within reach (no box), infinity a rigid box.
    double stiffness{0.0};
    /// Contact damping, N s/m (ignored for a rigid box).
    double damping{0.0};
  };

  /// What one probe measured.
  struct Probe {
    /// The noisy readings, N, in time order.
    std::vector<double> forces;
    /// Their noise-free values, N.
    std::vector<double> true_forces;
    /// Depth of the tip's lowest point below the surface at the end of the hold, m (negative: above it).
    double final_depth{0.0};
    /// Most contact points the tip had at one reading.
    int max_contact_points{0};
    /// Simulated time, s, and plant steps.
    double simulated_time{0.0};
    int steps{0};
  };

  /// Largest plant steps one probe may take ((push_time + hold_time) / time_step).
  static constexpr int kMaxSteps = 1000000;

  /// `arm` is the probe arm (data/robots/cairn_probe_arm.urdf: a welded base, joints yaw, pitch, push and a body
  /// "tip" with one sphere). Throws std::invalid_argument naming the value for a model without those joints or
  /// that body, or options out of range (non-positive times, gains or depth, noise < 0, samples outside
  /// [1, 100000], more than kMaxSteps steps).
  ProbeArmPlant(multibody::Model arm, const Options& options);
  /// Reads the arm's URDF first; errors name the file.
  static ProbeArmPlant Load(const std::string& urdf_path, const Options& options);

  const Options& options() const { return options_; }
  const multibody::Model& arm() const { return arm_; }
  /// Farthest horizontal distance from the base to a target on flat ground the arm reaches at full depth, m.
  double reach() const;

  /// Simulates one probe of the ground at `target` (world x-y) from a robot whose base is at `base` (x-y).
  /// Throws std::invalid_argument for a target beyond reach() (naming the distance) or a ground with a negative
  /// or NaN stiffness, a negative or non-finite damping, or a non-finite height.
  Probe Run(const Eigen::Vector2d& base, const Eigen::Vector2d& target, const Ground& ground, std::mt19937* rng) const;

 private:
  multibody::Model arm_;
  Options options_;
  int tip_body_{};
  double tip_radius_{};
  double push_min_{};
  double push_max_{};
};

}  // namespace cairn::planning
