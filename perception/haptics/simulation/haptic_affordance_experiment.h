#pragma once

/// @file
/// The experiments of seed 000 §4 on the simulated objects: leave-one-out, incremental learning, α against the
/// number of interactions, change detection, and data set 2 against data set 1.

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "cairn/perception/haptics/affordance_descriptor.h"
#include "cairn/perception/haptics/haptic_interaction_planner.h"
#include "cairn/perception/haptics/traversability_memory.h"
#include "cairn/perception/haptics/simulation/haptic_object_library.h"
#include "cairn/perception/haptics/simulation/simulated_antenna.h"
#include "cairn/perception/haptics/simulation/simulated_depth_sensor.h"

namespace cairn::perception {

/// A 2 x 2 confusion matrix: counts[actual][predicted], index 0 traversable, 1 non-traversable.
struct TraversabilityConfusion {
  std::array<std::array<int, 2>, 2> counts{};
  int total() const { return counts[0][0] + counts[0][1] + counts[1][0] + counts[1][1]; }
  /// Correct over total (0 when empty).
  double accuracy() const;
  void Add(bool actual_traversable, bool predicted_traversable);
};

/// One object seen by the robot.
struct HapticEncounter {
  HapticObjectKind kind{HapticObjectKind::kWall};
  /// The ground truth.
  bool traversable{false};
  /// The memory's answer before touching.
  AffordanceRecall recall;
  /// Points the planner kept for touching (eqs. 20–21) and what the antenna found (when it touched).
  int interaction_points{0};
  bool touched{false};
  bool blocked{false};
};

/// The simulated robot of the experiments and the experiments themselves. The sensor is mounted sensor_height
/// above the ground looking horizontally; the antenna base sits at X_CA in the sensor frame (the ground-truth
/// calibration, which §3.2's calibration recovers). Each approach views an object from a random heading and
/// distance (seeded), with fresh sensor noise.
class HapticAffordanceExperiment {
 public:
  struct Options {
    SimulatedDepthSensor::Options sensor{};
    SimulatedAntenna::Options antenna{};
    AffordanceDescriptor::Options descriptor{};
    TraversabilityMemory::Options memory{};
    HapticInteractionPlanner::Options planner{};
    double sensor_height{0.35};
    /// The antenna base in the sensor frame: 12 cm below and 5 cm ahead of it, tilted 5° down.
    Eigen::Isometry3d X_CA{Eigen::Translation3d(0.0, 0.12, 0.05) * Eigen::AngleAxisd(0.0873, Eigen::Vector3d::UnitX())};
    /// Approaches: distance from the object's origin (m) and heading off the object's front (rad).
    double min_distance{0.6};
    double max_distance{0.85};
    double max_heading{0.6};
    /// Approach samples per object in the leave-one-out and data set 2 → 1 experiments.
    int samples_per_object{4};
    std::uint64_t seed{1};
  };

  /// Most samples per object or encounters.
  static constexpr int kMaxSamples = 1000;

  /// Throws std::invalid_argument naming the first invalid option. The descriptor's reach centre is set to the
  /// antenna base.
  explicit HapticAffordanceExperiment(const Options& options);
  /// The default options.
  HapticAffordanceExperiment();

  /// The object's points (sensor frame) on approach `approach` (any integer; it seeds the view and the noise).
  Eigen::Matrix3Xd Observe(HapticObjectKind kind, int approach) const;
  /// The descriptor of an observation.
  AffordanceDescriptor Describe(const Eigen::Matrix3Xd& points_C) const;
  /// Plans with `confidence` and probes the object with the antenna (targets mapped to A by X_CA⁻¹).
  AntennaInteraction Touch(HapticObjectKind kind, int approach, const Eigen::Matrix3Xd& points_C, double confidence,
                           int* interaction_points) const;

  /// Leave-one-out over `kinds` (Fig. 12): the samples of one object are classified with a memory of the other
  /// objects' samples labelled by their ground truth (the paper's hand labels). Per-sample confusion.
  TraversabilityConfusion LeaveOneOut(const std::vector<HapticObjectKind>& kinds, int k) const;

  /// Incremental learning (Fig. 13): starting from `memory`, each kind is met `encounters` times in turn; every
  /// encounter recalls, touches (with the recall's confidence) and adds the haptic outcome to the memory.
  std::vector<HapticEncounter> Incremental(const std::vector<HapticObjectKind>& kinds, int encounters,
                                           TraversabilityMemory* memory) const;

  /// Fig. 15: interaction points for a fresh sample of `kind` after the memory holds n = 0..max_memory of its
  /// samples (labelled by ground truth), for each α. Result [alpha][n].
  std::vector<std::vector<int>> AlphaSweep(HapticObjectKind kind, const std::vector<double>& alphas,
                                           int max_memory) const;

  /// Table 3: every sample of each kind of `test_kinds` classified with k against a memory of the samples of
  /// `memory_kinds` labelled by their haptic interactions.
  std::vector<HapticEncounter> Transfer(const std::vector<HapticObjectKind>& memory_kinds,
                                        const std::vector<HapticObjectKind>& test_kinds, int k) const;

  /// One change-detection run (Table 5).
  struct ChangeRun {
    std::string name;
    /// |gist - reference| at each step until the change was detected.
    std::vector<double> differences;
    bool detected{false};
    /// The first step taken with the sensor past the object (-1 when it never left it, as when stuck).
    int exit_step{-1};
  };
  /// The four runs of Table 5: A-1 (shrub patch into open space), A-2 (into a wall), B (stuck in flimsy canes)
  /// and C (twigs into open space), with ω and the voxel of `detector`.
  std::vector<ChangeRun> ChangeDetection(double omega, double voxel) const;

  const Options& options() const { return options_; }
  /// Where the object stands and the sensor pose X_WC of an approach.
  Eigen::Isometry3d SensorPose(HapticObjectKind kind, int approach) const;

 private:
  Options options_;
  SimulatedDepthSensor sensor_;
  SimulatedAntenna antenna_;
};

}  // namespace cairn::perception
