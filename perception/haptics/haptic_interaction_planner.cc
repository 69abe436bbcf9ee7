#include "cairn/perception/haptics/haptic_interaction_planner.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>
#include <string>

#include "cairn/common/number_text.h"
#include "cairn/perception/haptics/point_cloud_reduction.h"

namespace cairn::perception {
namespace {

constexpr double kPi = 3.14159265358979323846;

void CheckFinite(double value, const char* name) {
  if (!std::isfinite(value)) throw std::invalid_argument(std::string(name) + " is " + FormatShort(value) + "; it must be finite");
}

void CheckPositive(double value, const char* name) {
  if (!(value > 0.0) || !std::isfinite(value)) {
    throw std::invalid_argument(std::string(name) + " is " + FormatShort(value) + "; it must be positive and finite");
  }
}

void CheckWeight(double value, const char* name) {
  if (!(value >= 0.0) || !(value <= 1.0)) {
    throw std::invalid_argument(std::string(name) + " is " + FormatShort(value) + "; a weight must lie in [0, 1]");
  }
}

}  // namespace

HapticInteractionPlanner::HapticInteractionPlanner() : HapticInteractionPlanner(Options{}) {}

HapticInteractionPlanner::HapticInteractionPlanner(const Options& options) : options_(options) { Validate(options); }

void HapticInteractionPlanner::Validate(const Options& o) {
  CheckPositive(o.voxel, "voxel");
  CheckPositive(o.min_candidate_spacing, "min_candidate_spacing");
  CheckFinite(o.ground_offset, "ground_offset");
  CheckPositive(o.sigma, "sigma");
  CheckPositive(o.neighbour_radius, "neighbour_radius");
  CheckWeight(o.theta_height, "theta_height");
  CheckWeight(o.theta_centroid, "theta_centroid");
  CheckWeight(o.theta_density, "theta_density");
  const double sum = o.theta_height + o.theta_centroid + o.theta_density;
  if (std::abs(sum - 1.0) > 1e-9) {
    throw std::invalid_argument("theta_height + theta_centroid + theta_density is " + FormatShort(sum) +
                                "; the weights of eq. 19 must sum to 1 (the paper uses 0.3, 0.2, 0.5)");
  }
  if (!(o.alpha >= 0.0) || !std::isfinite(o.alpha)) {
    throw std::invalid_argument("alpha is " + FormatShort(o.alpha) + "; it must be non-negative and finite");
  }
  if (!(o.push_distance >= 0.0) || !std::isfinite(o.push_distance)) {
    throw std::invalid_argument("push_distance is " + FormatShort(o.push_distance) +
                                " m; it must be non-negative and finite");
  }
}

std::vector<InteractionPoint> HapticInteractionPlanner::ScoreCandidates(const Eigen::Matrix3Xd& object_C) const {
  const Eigen::Matrix3Xd voxels = VoxelGridCentroids(object_C, options_.voxel);
  if (voxels.cols() > kMaxPlanPoints) {
    throw std::invalid_argument("the object has " + FormatShort(static_cast<long long>(voxels.cols())) + " voxels of " +
                                FormatShort(options_.voxel) + " m; at most " + FormatShort(kMaxPlanPoints) +
                                " are planned over (cut the cloud to the object)");
  }
  std::vector<InteractionPoint> result;
  if (voxels.cols() == 0) return result;
  const Eigen::Matrix3Xd candidates = DownsampleByMinDistance(voxels, options_.min_candidate_spacing);
  const Eigen::Vector3d centroid = voxels.rowwise().mean();
  const double two_sigma2 = 2.0 * options_.sigma * options_.sigma;
  const double r2 = options_.neighbour_radius * options_.neighbour_radius;
  const double full = 2.0 * kPi * r2 / (options_.voxel * options_.voxel);  // eq. 18
  result.reserve(static_cast<std::size_t>(candidates.cols()));
  for (Eigen::Index i = 0; i < candidates.cols(); ++i) {
    InteractionPoint point;
    point.p_C = candidates.col(i);
    const double dy = point.p_C.y() - options_.ground_offset;
    point.height_score = std::exp(-dy * dy / two_sigma2);
    point.centroid_score = std::exp(-(point.p_C - centroid).squaredNorm() / two_sigma2);
    // The candidate is itself a voxel centroid; it is not its own neighbour.
    const double neighbours =
        static_cast<double>(((voxels.colwise() - point.p_C).colwise().squaredNorm().array() <= r2).count()) - 1.0;
    point.density_score = std::min(1.0, std::max(0.0, neighbours) / full);
    point.score = options_.theta_height * point.height_score + options_.theta_centroid * point.centroid_score +
                  options_.theta_density * point.density_score;
    result.push_back(point);
  }
  std::stable_sort(result.begin(), result.end(),
                   [](const InteractionPoint& a, const InteractionPoint& b) { return a.score > b.score; });
  return result;
}

std::vector<InteractionPoint> HapticInteractionPlanner::Prune(const std::vector<InteractionPoint>& sorted,
                                                              double confidence) const {
  if (!(confidence >= 0.0) || !(confidence <= 1.0)) {
    throw std::invalid_argument("the recall confidence is " + FormatShort(confidence) + "; it must lie in [0, 1]");
  }
  const double threshold = options_.alpha * confidence;
  std::vector<InteractionPoint> kept;
  for (const InteractionPoint& p : sorted) {
    if (p.score > threshold) kept.push_back(p);
  }
  return kept;
}

std::vector<InteractionPoint> HapticInteractionPlanner::ExecutionOrder(const std::vector<InteractionPoint>& points) {
  std::vector<InteractionPoint> order;
  if (points.empty()) return order;
  std::vector<bool> used(points.size(), false);
  std::size_t current = 0;
  for (std::size_t i = 1; i < points.size(); ++i) {
    if (points[i].p_C.x() > points[current].p_C.x()) current = i;
  }
  order.reserve(points.size());
  for (;;) {
    used[current] = true;
    order.push_back(points[current]);
    if (order.size() == points.size()) break;
    std::size_t next = points.size();
    double best = 0.0;
    for (std::size_t i = 0; i < points.size(); ++i) {
      if (used[i]) continue;
      const double d2 = (points[i].p_C - points[current].p_C).squaredNorm();
      if (next == points.size() || d2 < best) {
        next = i;
        best = d2;
      }
    }
    current = next;
  }
  return order;
}

InteractionPlan HapticInteractionPlanner::Plan(const Eigen::Matrix3Xd& object_C, double confidence) const {
  InteractionPlan plan;
  plan.candidates = ScoreCandidates(object_C);
  plan.threshold = options_.alpha * confidence;
  plan.selected = ExecutionOrder(Prune(plan.candidates, confidence));
  plan.targets_C.reserve(plan.selected.size());
  for (const InteractionPoint& p : plan.selected) {
    plan.targets_C.push_back(p.p_C + Eigen::Vector3d(0.0, 0.0, options_.push_distance));
  }
  return plan;
}

}  // namespace cairn::perception
