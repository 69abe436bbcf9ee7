#pragma once

/// @file
/// ProbingPlanner: where to probe questionable terrain next (seed 001 §5.3).

#include <cstdint>
#include <map>
#include <utility>
#include <vector>

#include <Eigen/Core>

namespace cairn::planning {

/// Chooses probe points on questionable terrain (seed 001 §5.3): the semantically labelled points whose
/// collapsibility is not yet known are clustered (points of one class closer than cluster_distance are
/// connected), each cluster is down-sampled to candidate probe points (one per candidate_spacing square), and
/// the candidate nearest the robot is the target. Within the arm's reach the robot pauses and probes; the
/// result is then assigned to the whole cluster, whose candidates leave the planner (RecordProbe), and the path
/// resumes. A cluster that later grows out of a probed one (the same class, touching its points) inherits that
/// probe's collapsibility instead of being probed again.
///
/// Deterministic: clusters are ordered by their lowest point index, candidates by position, ties by index.
class ProbingPlanner {
 public:
  /// Most points one call may hold.
  static constexpr int kMaxPoints = 1 << 22;
  /// Largest |coordinate| of a point, m (so that bucket indices stay exact).
  static constexpr double kMaxCoordinate = 1e6;
  /// Most point pairs one FindClusters or TouchingProbe call may compare. Points are compared within buckets of
  /// side cluster_distance, so a cluster_distance much larger than the point spacing makes the work quadratic;
  /// such calls are refused instead of running for hours.
  static constexpr long long kMaxPairComparisons = 1LL << 28;

  struct Options {
    /// Points of one class closer than this (m) belong to one cluster.
    double cluster_distance{0.15};
    /// Side (m) of the squares that down-sample a cluster to candidates.
    double candidate_spacing{0.3};
    /// The arm's reach (m) from the robot's position: a target within it is probed (seed 001: the arm's
    /// kinematically reachable region).
    double reach{0.8};
    /// Clusters with fewer points are segmentation noise and never probed.
    int min_cluster_points{3};
  };

  /// A connected set of questionable points of one class.
  struct Cluster {
    int label{-1};
    /// Indices into the points given to FindClusters, increasing.
    std::vector<int> members;
    /// Down-sampled candidate probe points.
    std::vector<Eigen::Vector2d> candidates;
  };

  /// What to do now.
  struct Decision {
    enum class Action {
      kNone,      ///< nothing questionable left to probe
      kApproach,  ///< the nearest candidate is out of reach: keep following the path
      kProbe,     ///< pause, probe `target`, RecordProbe, resume
    };
    Action action{Action::kNone};
    int cluster{-1};
    Eigen::Vector2d target{Eigen::Vector2d::Zero()};
    double distance{0.0};
  };

  /// A recorded probe.
  struct Probe {
    int label{-1};
    Eigen::Vector2d target{Eigen::Vector2d::Zero()};
    double collapsibility{0.0};
  };

  /// Throws std::invalid_argument for distances that are not finite or not in [1e-6, 1e6] m, or a minimum cluster
  /// size below 1.
  explicit ProbingPlanner(const Options& options);
  ProbingPlanner() : ProbingPlanner(Options{}) {}

  const Options& options() const { return options_; }

  /// Clusters `points` (2 x N, world x-y) by class `labels` (N values; negative = not questionable, skipped).
  /// Throws std::invalid_argument for mismatched sizes, more than kMaxPoints points, a point that is not
  /// finite or beyond kMaxCoordinate, or more than kMaxPairComparisons pairs to compare (naming cluster_distance).
  std::vector<Cluster> FindClusters(const Eigen::Matrix2Xd& points, const std::vector<int>& labels) const;

  /// The recorded probe a cluster grows out of (same class, a point within cluster_distance of the probed
  /// cluster's points), or -1. Throws std::invalid_argument for a member that is not a column of `points`, or
  /// for more than kMaxPairComparisons pairs to compare.
  int TouchingProbe(const Cluster& cluster, const Eigen::Matrix2Xd& points) const;

  /// The nearest candidate of the clusters big enough and not touching a recorded probe, seen from `robot`.
  Decision Decide(const std::vector<Cluster>& clusters, const Eigen::Matrix2Xd& points,
                  const Eigen::Vector2d& robot) const;

  /// Records the probe of `cluster` at `target` with collapsibility `collapsibility` (in [0, 1]; throws
  /// std::invalid_argument otherwise, and for a member that is not a column of `points` or a point that
  /// FindClusters would refuse); its points then absorb the clusters that grow out of it.
  void RecordProbe(const Cluster& cluster, const Eigen::Matrix2Xd& points, const Eigen::Vector2d& target,
                   double collapsibility);

  const std::vector<Probe>& probes() const { return probes_; }

 private:
  using Key = std::pair<std::int64_t, std::int64_t>;
  Key BucketOf(const Eigen::Vector2d& p) const;

  Options options_;
  std::vector<Probe> probes_;
  // Probed points by bucket of side cluster_distance, with the probe's index.
  std::map<Key, std::vector<std::pair<Eigen::Vector2d, int>>> probed_points_;
};

}  // namespace cairn::planning
