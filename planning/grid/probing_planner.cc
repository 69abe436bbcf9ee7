#include "cairn/planning/grid/probing_planner.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <string>

#include "cairn/common/number_text.h"

namespace cairn::planning {

namespace {

int Find(std::vector<int>& parent, int x) {
  while (parent[x] != x) {
    parent[x] = parent[parent[x]];
    x = parent[x];
  }
  return x;
}

void Union(std::vector<int>& parent, int a, int b) {
  a = Find(parent, a);
  b = Find(parent, b);
  if (a == b) return;
  if (a < b) std::swap(a, b);
  parent[a] = b;  // the lower index is the root, so clusters are named by their first point
}

std::invalid_argument TooManyPairs(long long pairs, double cluster_distance) {
  return std::invalid_argument("ProbingPlanner: cluster_distance " + FormatShort(cluster_distance) + " m needs " +
                               FormatShort(static_cast<double>(pairs)) + " point-pair comparisons, more than the " +
                               "limit of " + FormatShort(static_cast<double>(ProbingPlanner::kMaxPairComparisons)) +
                               "; use a cluster_distance near the points' spacing (e.g. 1.5 map cells)");
}

}  // namespace

ProbingPlanner::ProbingPlanner(const Options& options) : options_(options) {
  for (const auto& [name, value] : {std::pair<const char*, double>{"cluster_distance", options.cluster_distance},
                                    {"candidate_spacing", options.candidate_spacing},
                                    {"reach", options.reach}}) {
    if (!(value >= 1e-6 && value <= 1e6)) {
      throw std::invalid_argument(std::string("ProbingPlanner: ") + name + " " + FormatShort(value) +
                                  " m must be in [1e-6, 1e6]");
    }
  }
  if (options.min_cluster_points < 1) {
    throw std::invalid_argument("ProbingPlanner: min_cluster_points " + FormatShort(options.min_cluster_points) +
                                " must be at least 1");
  }
}

ProbingPlanner::Key ProbingPlanner::BucketOf(const Eigen::Vector2d& p) const {
  return {static_cast<std::int64_t>(std::floor(p.x() / options_.cluster_distance)),
          static_cast<std::int64_t>(std::floor(p.y() / options_.cluster_distance))};
}

std::vector<ProbingPlanner::Cluster> ProbingPlanner::FindClusters(const Eigen::Matrix2Xd& points,
                                                                  const std::vector<int>& labels) const {
  if (points.cols() > kMaxPoints) {
    throw std::invalid_argument("ProbingPlanner: " + FormatShort(static_cast<long>(points.cols())) +
                                " points exceed the limit of " + FormatShort(kMaxPoints));
  }
  if (static_cast<long>(labels.size()) != points.cols()) {
    throw std::invalid_argument("ProbingPlanner: " + FormatShort(static_cast<unsigned long>(labels.size())) +
                                " labels for " + FormatShort(static_cast<long>(points.cols())) +
                                " points (give one label per point)");
  }
  const int n = static_cast<int>(points.cols());
  for (int k = 0; k < n; ++k) {
    if (!points.col(k).allFinite() || points.col(k).cwiseAbs().maxCoeff() > kMaxCoordinate) {
      throw std::invalid_argument("ProbingPlanner: point " + FormatShort(k) + " (" + FormatShort(points(0, k)) + ", " +
                                  FormatShort(points(1, k)) + ") must be finite and within +-" +
                                  FormatShort(kMaxCoordinate) + " m");
    }
  }
  std::map<Key, std::vector<int>> buckets;
  for (int k = 0; k < n; ++k) {
    if (labels[k] >= 0) buckets[BucketOf(points.col(k))].push_back(k);
  }
  // Count the comparisons first: a bucket holding most points makes the loop below quadratic.
  long long pairs = 0;
  for (const auto& [key, members] : buckets) {
    for (std::int64_t dx = -1; dx <= 1; ++dx) {
      for (std::int64_t dy = -1; dy <= 1; ++dy) {
        const auto it = buckets.find({key.first + dx, key.second + dy});
        if (it != buckets.end()) pairs += static_cast<long long>(members.size()) * it->second.size();
      }
    }
    if (pairs > kMaxPairComparisons) throw TooManyPairs(pairs, options_.cluster_distance);
  }
  std::vector<int> parent(n);
  std::iota(parent.begin(), parent.end(), 0);
  const double d2 = options_.cluster_distance * options_.cluster_distance;
  for (const auto& [key, members] : buckets) {
    for (std::int64_t dx = -1; dx <= 1; ++dx) {
      for (std::int64_t dy = -1; dy <= 1; ++dy) {
        const auto it = buckets.find({key.first + dx, key.second + dy});
        if (it == buckets.end()) continue;
        for (int a : members) {
          for (int b : it->second) {
            if (b <= a || labels[a] != labels[b]) continue;
            if ((points.col(a) - points.col(b)).squaredNorm() <= d2) Union(parent, a, b);
          }
        }
      }
    }
  }
  std::map<int, int> cluster_of_root;
  std::vector<Cluster> clusters;
  for (int k = 0; k < n; ++k) {
    if (labels[k] < 0) continue;
    const int root = Find(parent, k);
    auto [it, inserted] = cluster_of_root.emplace(root, static_cast<int>(clusters.size()));
    if (inserted) {
      clusters.emplace_back();
      clusters.back().label = labels[k];
    }
    clusters[it->second].members.push_back(k);
  }
  const double spacing = options_.candidate_spacing;
  for (Cluster& c : clusters) {
    // One candidate per square: the member nearest the square's centre (ties: the lower index).
    std::map<Key, std::pair<double, int>> best;
    for (int k : c.members) {
      const Eigen::Vector2d p = points.col(k);
      const Key key{static_cast<std::int64_t>(std::floor(p.x() / spacing)),
                    static_cast<std::int64_t>(std::floor(p.y() / spacing))};
      const Eigen::Vector2d centre((key.first + 0.5) * spacing, (key.second + 0.5) * spacing);
      const double d = (p - centre).squaredNorm();
      auto it = best.find(key);
      if (it == best.end() || d < it->second.first) best[key] = {d, k};
    }
    for (const auto& [key, entry] : best) c.candidates.push_back(points.col(entry.second));
  }
  return clusters;
}

int ProbingPlanner::TouchingProbe(const Cluster& cluster, const Eigen::Matrix2Xd& points) const {
  const double d2 = options_.cluster_distance * options_.cluster_distance;
  int found = -1;
  long long pairs = 0;
  for (int k : cluster.members) {
    if (k < 0 || k >= points.cols()) {
      throw std::invalid_argument("ProbingPlanner: cluster member " + FormatShort(k) + " is not a column of the " +
                                  FormatShort(static_cast<long>(points.cols())) +
                                  " points given (pass the points the cluster was found in)");
    }
    const Eigen::Vector2d p = points.col(k);
    const Key key = BucketOf(p);
    for (std::int64_t dx = -1; dx <= 1; ++dx) {
      for (std::int64_t dy = -1; dy <= 1; ++dy) {
        const auto it = probed_points_.find({key.first + dx, key.second + dy});
        if (it != probed_points_.end()) pairs += static_cast<long long>(it->second.size());
      }
    }
    if (pairs > kMaxPairComparisons) throw TooManyPairs(pairs, options_.cluster_distance);
    for (std::int64_t dx = -1; dx <= 1; ++dx) {
      for (std::int64_t dy = -1; dy <= 1; ++dy) {
        const auto it = probed_points_.find({key.first + dx, key.second + dy});
        if (it == probed_points_.end()) continue;
        for (const auto& [q, probe] : it->second) {
          if (probes_[probe].label == cluster.label && (p - q).squaredNorm() <= d2 &&
              (found < 0 || probe < found)) {
            found = probe;
          }
        }
      }
    }
  }
  return found;
}

ProbingPlanner::Decision ProbingPlanner::Decide(const std::vector<Cluster>& clusters, const Eigen::Matrix2Xd& points,
                                                const Eigen::Vector2d& robot) const {
  Decision decision;
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t c = 0; c < clusters.size(); ++c) {
    const Cluster& cluster = clusters[c];
    if (static_cast<int>(cluster.members.size()) < options_.min_cluster_points) continue;
    if (TouchingProbe(cluster, points) >= 0) continue;
    for (const Eigen::Vector2d& candidate : cluster.candidates) {
      const double d = (candidate - robot).norm();
      if (d < best) {
        best = d;
        decision.cluster = static_cast<int>(c);
        decision.target = candidate;
        decision.distance = d;
      }
    }
  }
  if (decision.cluster >= 0) {
    decision.action = best <= options_.reach ? Decision::Action::kProbe : Decision::Action::kApproach;
  }
  return decision;
}

void ProbingPlanner::RecordProbe(const Cluster& cluster, const Eigen::Matrix2Xd& points, const Eigen::Vector2d& target,
                                 double collapsibility) {
  if (!(collapsibility >= 0.0 && collapsibility <= 1.0)) {
    throw std::invalid_argument("ProbingPlanner: collapsibility " + FormatShort(collapsibility) +
                                " must be in [0, 1] (eq. 5)");
  }
  for (int k : cluster.members) {
    if (k < 0 || k >= points.cols() || !points.col(k).allFinite() ||
        points.col(k).cwiseAbs().maxCoeff() > kMaxCoordinate) {
      throw std::invalid_argument("ProbingPlanner: cluster member " + FormatShort(k) +
                                  " is not a finite point of the points given (within +-1e6 m)");
    }
  }
  const int index = static_cast<int>(probes_.size());
  probes_.push_back(Probe{cluster.label, target, collapsibility});
  for (int k : cluster.members) {
    probed_points_[BucketOf(points.col(k))].emplace_back(points.col(k), index);
  }
}

}  // namespace cairn::planning
