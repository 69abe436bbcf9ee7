#pragma once

/// @file
/// TraverseScenario: a traversability-with-probing scenario (seed 001 §6.1) read from YAML (docs/traverse.md).

#include <cstddef>
#include <string>
#include <vector>

#include <Eigen/Core>

namespace cairn::planning {

/// The ground truth and settings of a probing run: a rectangular world of flat ground with box regions of rocks
/// (rough bumps), plants and water (semantic classes, seen by a simulated segmenter), each of plants and water
/// with the stiffness of the ground beneath (soft soil, deep water with none, hard soil); the robot's start and
/// goal; the simulated depth sensor, probe and planner settings. Errors name the file, the line and the key.
class TraverseScenario {
 public:
  /// What a region is.
  enum class Kind { kRocks, kPlants, kWater };

  struct Region {
    std::string name;
    Kind kind{Kind::kPlants};
    Eigen::Vector2d min{Eigen::Vector2d::Zero()};
    Eigen::Vector2d max{Eigen::Vector2d::Zero()};
    /// Stiffness of the ground under plants or water, N/m (0: no support, deep water).
    double stiffness{0.0};
    /// Peak height of the rocks' bumps, m.
    double rock_height{0.3};
    bool Contains(const Eigen::Vector2d& p) const {
      return (p.array() >= min.array()).all() && (p.array() < max.array()).all();
    }
  };

  /// Limits on what a file may state: regions, the world's cells (the map is world size / resolution), ticks,
  /// probe samples, sensor points per scan.
  static constexpr std::size_t kMaxRegions = 256;
  static constexpr long long kMaxCells = 1 << 22;
  static constexpr int kMaxTicks = 100000;
  static constexpr int kMaxProbeSamples = 100000;
  static constexpr long long kMaxPointsPerScan = 1 << 21;
  /// Largest scenario file (1 MiB), refused before parsing.
  static constexpr std::size_t kMaxFileBytes = 1u << 20;

  /// World (and global map) rectangle and cell size, m.
  Eigen::Vector2d world_min{0.0, 0.0};
  Eigen::Vector2d world_size{10.0, 10.0};
  double resolution{0.1};
  Eigen::Vector2d start{1.0, 5.0};
  Eigen::Vector2d goal{9.0, 5.0};

  /// The simulated depth sensor sees the ground within `sensor_range` of the robot, sampled every
  /// `point_spacing` m, from `sensor_height` above it, with the D435 noise model; the segmenter gives the true
  /// class probability `segmentation_confidence`.
  double sensor_range{3.0};
  double sensor_height{0.5};
  double point_spacing{0.05};
  double segmentation_confidence{0.9};
  int seed{1};

  /// Distance walked per tick, m, and the most ticks.
  double step{0.1};
  int max_ticks{1500};

  /// How a probe's force is simulated.
  enum class ProbeModel {
    /// The arm in the physics plant (ProbeArmPlant): the tip pushes into a terrain box whose contact stiffness is
    /// the ground's (none under deep water); the default, as seed 001 simulates it.
    kPlant,
    /// The force is stiffness x depth directly (fast, no arm or contact dynamics).
    kSpring,
  };

  /// Probe: the arm pushes `probe_depth` into the ground; the force (stiffness x depth at rest, with the plant
  /// model) plus Gaussian noise of `force_noise` N is sampled `probe_samples` times and averaged (eq. 5 with
  /// F_hard = `hard_force`); the arm reaches `reach` m from the robot. `ground_stiffness` is that of plain ground
  /// outside the regions; `probe_damping` (N s/m) is the contact damping of every ground with support.
  ProbeModel probe_model{ProbeModel::kPlant};
  double probe_damping{50.0};
  double probe_depth{0.02};
  double hard_force{100.0};
  double force_noise{2.0};
  int probe_samples{20};
  double reach{0.8};
  double ground_stiffness{8000.0};

  /// Cells with a traversability below this are blocked for the planner.
  double blocked_below{0.25};

  std::vector<Region> regions;

  /// Reads a scenario file. Throws std::invalid_argument naming the file, line and key for a mistake: unknown
  /// keys, values out of range, a region outside the world, a start or goal outside the world, or a limit
  /// exceeded.
  static TraverseScenario Load(const std::string& path);
  /// Parses `text` as if read from `path`.
  static TraverseScenario FromText(const std::string& path, const std::string& text);

  /// The first region containing p (the file's order), or null.
  const Region* RegionAt(const Eigen::Vector2d& p) const;
  /// True ground height at p (rocks are bumps; everything else is flat at 0).
  double HeightAt(const Eigen::Vector2d& p) const;
  /// Semantic class at p: 0 plants, 1 water, -1 none.
  int ClassAt(const Eigen::Vector2d& p) const;
  /// Stiffness of the ground at p, N/m.
  double StiffnessAt(const Eigen::Vector2d& p) const;
  /// The collapsibility a noiseless probe would measure at p (eq. 5).
  double TrueCollapsibility(const Eigen::Vector2d& p) const;
  /// "rocks", "plants" or "water".
  static std::string KindName(Kind kind);
};

}  // namespace cairn::planning
