#pragma once

#include <vector>

#include <Eigen/Core>

namespace cairn::perception {

/// Friction-annotated points in the world frame (thesis 5.2.1): what footstep planning reads the friction bound
/// of a contact from. Each point keeps its quantile Q_{1−η} and its material mixture weights (registry order), so
/// a planner or a contact update can use the whole distribution, not just the bound.
struct FrictionPointCloud {
  std::vector<Eigen::Vector3d> points_W;
  std::vector<float> quantiles;
  /// num_points x num_labels.
  Eigen::MatrixXf weights;
  int size() const { return static_cast<int>(points_W.size()); }
};

}  // namespace cairn::perception
