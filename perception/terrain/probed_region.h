#pragma once

/// @file
/// ProbedRegion: the result of one probe, assigned to the region it stands for.

#include <vector>

#include <Eigen/Core>

namespace cairn::perception {

/// A probe's collapsibility C (eq. 5) and the points (world x-y) of the semantic cluster it was assigned to
/// (seed 001 §5.3: one probe per questionable region).
struct ProbedRegion {
  std::vector<Eigen::Vector2d> points;
  double collapsibility{0.0};
};

}  // namespace cairn::perception
