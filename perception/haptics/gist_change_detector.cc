#include "cairn/perception/haptics/gist_change_detector.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include "cairn/common/number_text.h"
#include "cairn/perception/haptics/point_cloud_reduction.h"

namespace cairn::perception {

GistChangeDetector::GistChangeDetector() : GistChangeDetector(Options{}) {}

GistChangeDetector::GistChangeDetector(const Options& options) : options_(options) {
  if (!(options.voxel > 0.0) || !std::isfinite(options.voxel)) {
    throw std::invalid_argument("the gist voxel is " + FormatShort(options.voxel) +
                                " m; it must be positive and finite (the paper uses 0.01)");
  }
  if (!(options.omega >= 0.0) || !std::isfinite(options.omega)) {
    throw std::invalid_argument("omega is " + FormatShort(options.omega) +
                                "; the change threshold must be non-negative and finite (the paper uses 0.03)");
  }
}

double GistChangeDetector::Gist(const Eigen::Matrix3Xd& points, double voxel) {
  const std::int64_t voxels = CountOccupiedVoxels(points, voxel);
  if (points.cols() == 0) return 0.0;
  return static_cast<double>(voxels) / static_cast<double>(points.cols());
}

void GistChangeDetector::SetReference(const Eigen::Matrix3Xd& points) {
  reference_ = Gist(points, options_.voxel);
  has_reference_ = true;
}

void GistChangeDetector::SetReferenceGist(double gist) {
  if (!(gist >= 0.0) || !(gist <= 1.0)) {
    throw std::invalid_argument("the reference gist is " + FormatShort(gist) + "; a gist lies in [0, 1]");
  }
  reference_ = gist;
  has_reference_ = true;
}

GistChangeDetector::Result GistChangeDetector::Compare(const Eigen::Matrix3Xd& points) const {
  if (!has_reference_) {
    throw std::logic_error("GistChangeDetector::Compare called before SetReference: take the reference gist first");
  }
  Result result;
  result.gist = Gist(points, options_.voxel);
  result.difference = std::abs(result.gist - reference_);
  result.changed = result.difference > options_.omega;
  return result;
}

}  // namespace cairn::perception
