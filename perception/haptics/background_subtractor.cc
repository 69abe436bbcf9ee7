#include "cairn/perception/haptics/background_subtractor.h"

#include <vector>

#include "cairn/perception/haptics/internal/voxel_key.h"

namespace cairn::perception {

BackgroundSubtractor::BackgroundSubtractor(const Eigen::Matrix3Xd& reference, double resolution)
    : resolution_(resolution) {
  internal::CheckPositiveLength(resolution, "the background resolution");
  internal::CheckCloudSize(reference, "the reference cloud");
  cells_.reserve(static_cast<std::size_t>(reference.cols()));
  for (Eigen::Index i = 0; i < reference.cols(); ++i) {
    cells_.insert(internal::KeyOf(internal::CellOf(reference.col(i), resolution, i)));
  }
}

Eigen::Matrix3Xd BackgroundSubtractor::Foreground(const Eigen::Matrix3Xd& points) const {
  internal::CheckCloudSize(points, "the cloud to segment");
  std::vector<Eigen::Index> kept;
  for (Eigen::Index i = 0; i < points.cols(); ++i) {
    if (cells_.count(internal::KeyOf(internal::CellOf(points.col(i), resolution_, i))) == 0) kept.push_back(i);
  }
  Eigen::Matrix3Xd result(3, static_cast<Eigen::Index>(kept.size()));
  for (std::size_t k = 0; k < kept.size(); ++k) result.col(static_cast<Eigen::Index>(k)) = points.col(kept[k]);
  return result;
}

}  // namespace cairn::perception
