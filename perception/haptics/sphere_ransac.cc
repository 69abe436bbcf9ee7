#include "cairn/perception/haptics/sphere_ransac.h"

#include <cmath>
#include <random>
#include <stdexcept>
#include <string>

#include <Eigen/Dense>

#include "cairn/common/number_text.h"
#include "cairn/perception/haptics/point_cloud_reduction.h"

namespace cairn::perception {
namespace {

// Least-squares algebraic sphere |p|² + a·p + d = 0 through the given points; false when degenerate.
bool FitAlgebraic(const Eigen::Matrix3Xd& points, const std::vector<int>& indices, Eigen::Vector3d* center,
                  double* radius) {
  Eigen::MatrixXd A(static_cast<Eigen::Index>(indices.size()), 4);
  Eigen::VectorXd b(static_cast<Eigen::Index>(indices.size()));
  for (std::size_t r = 0; r < indices.size(); ++r) {
    const Eigen::Vector3d p = points.col(indices[r]);
    A.row(static_cast<Eigen::Index>(r)) << p.x(), p.y(), p.z(), 1.0;
    b[static_cast<Eigen::Index>(r)] = -p.squaredNorm();
  }
  const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(A);
  if (qr.rank() < 4) return false;
  const Eigen::Vector4d x = qr.solve(b);
  *center = -0.5 * x.head<3>();
  const double r2 = center->squaredNorm() - x[3];
  if (!(r2 > 0.0)) return false;
  *radius = std::sqrt(r2);
  return true;
}

}  // namespace

SphereRansac::SphereRansac() : SphereRansac(Options{}) {}

SphereRansac::SphereRansac(const Options& options) : options_(options) {
  if (options.iterations < 1 || options.iterations > kMaxIterations) {
    throw std::invalid_argument("iterations is " + FormatShort(options.iterations) + "; it must be between 1 and " +
                                FormatShort(kMaxIterations));
  }
  if (!(options.inlier_threshold > 0.0) || !std::isfinite(options.inlier_threshold)) {
    throw std::invalid_argument("inlier_threshold is " + FormatShort(options.inlier_threshold) +
                                " m; it must be positive and finite");
  }
  if (!(options.min_radius >= 0.0) || !(options.max_radius > options.min_radius) ||
      !std::isfinite(options.max_radius)) {
    throw std::invalid_argument("the radius bounds [" + FormatShort(options.min_radius) + ", " +
                                FormatShort(options.max_radius) + "] m must be finite with 0 <= min < max");
  }
}

bool SphereRansac::SphereThrough(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c,
                                 const Eigen::Vector3d& d, Eigen::Vector3d* center, double* radius) {
  // Subtracting a's equation from the others leaves 2 (q - a)·x = |q|² - |a|², linear in the centre x.
  Eigen::Matrix3d M;
  M.row(0) = 2.0 * (b - a).transpose();
  M.row(1) = 2.0 * (c - a).transpose();
  M.row(2) = 2.0 * (d - a).transpose();
  const Eigen::Vector3d rhs(b.squaredNorm() - a.squaredNorm(), c.squaredNorm() - a.squaredNorm(),
                            d.squaredNorm() - a.squaredNorm());
  const double scale = M.rowwise().norm().prod();
  const double det = M.determinant();
  if (!(scale > 0.0) || !(std::abs(det) > 1e-9 * scale)) return false;
  *center = M.inverse() * rhs;
  *radius = (a - *center).norm();
  return std::isfinite(*radius);
}

SphereFit SphereRansac::Fit(const Eigen::Matrix3Xd& points) const {
  if (points.cols() < 4) {
    throw std::invalid_argument("a sphere needs at least 4 points; the cloud has " +
                                FormatShort(static_cast<long long>(points.cols())));
  }
  if (points.cols() > kMaxHapticCloudPoints) {
    throw std::invalid_argument("the cloud has " + FormatShort(static_cast<long long>(points.cols())) +
                                " points; at most " + FormatShort(static_cast<long long>(kMaxHapticCloudPoints)) +
                                " are fitted");
  }
  if (!points.allFinite()) throw std::invalid_argument("the cloud to fit a sphere to holds a non-finite point");
  std::mt19937_64 rng(options_.seed);
  const auto n = static_cast<std::uint64_t>(points.cols());
  SphereFit best;
  int best_count = -1;
  for (int it = 0; it < options_.iterations; ++it) {
    int idx[4];
    for (int k = 0; k < 4; ++k) {
      bool fresh = false;
      while (!fresh) {
        idx[k] = static_cast<int>(rng() % n);
        fresh = true;
        for (int j = 0; j < k; ++j) fresh = fresh && idx[j] != idx[k];
      }
    }
    Eigen::Vector3d center;
    double radius = 0.0;
    if (!SphereThrough(points.col(idx[0]), points.col(idx[1]), points.col(idx[2]), points.col(idx[3]), &center,
                       &radius)) {
      continue;
    }
    if (radius < options_.min_radius || radius > options_.max_radius) continue;
    const int count = static_cast<int>(
        (((points.colwise() - center).colwise().norm().array() - radius).abs() <= options_.inlier_threshold).count());
    if (count > best_count) {
      best_count = count;
      best.center = center;
      best.radius = radius;
    }
  }
  best.iterations = options_.iterations;
  if (best_count < 0) {
    throw std::runtime_error("no sphere with a radius in [" + FormatShort(options_.min_radius) + ", " +
                             FormatShort(options_.max_radius) + "] m was found in " +
                             FormatShort(options_.iterations) + " RANSAC hypotheses over " +
                             FormatShort(static_cast<long long>(points.cols())) + " points");
  }
  const auto collect = [&](const Eigen::Vector3d& center, double radius) {
    std::vector<int> inliers;
    for (Eigen::Index i = 0; i < points.cols(); ++i) {
      if (std::abs((points.col(i) - center).norm() - radius) <= options_.inlier_threshold) {
        inliers.push_back(static_cast<int>(i));
      }
    }
    return inliers;
  };
  best.inliers = collect(best.center, best.radius);
  Eigen::Vector3d refined_center;
  double refined_radius = 0.0;
  if (best.inliers.size() >= 4 && FitAlgebraic(points, best.inliers, &refined_center, &refined_radius) &&
      refined_radius >= options_.min_radius && refined_radius <= options_.max_radius) {
    std::vector<int> refined = collect(refined_center, refined_radius);
    // The refit is kept only when it explains at least as many points.
    if (refined.size() >= best.inliers.size()) {
      best.center = refined_center;
      best.radius = refined_radius;
      best.inliers = std::move(refined);
    }
  }
  // The hypothesis' own three or four points are inliers up to rounding; at coordinates far from the origin
  // rounding can leave none, and there is no centroid to report.
  if (best.inliers.empty()) {
    throw std::runtime_error("the best RANSAC sphere (radius " + FormatShort(best.radius) + " m) has no inlier within " +
                             FormatShort(options_.inlier_threshold) + " m; move the cloud near the origin or widen "
                             "the inlier threshold");
  }
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  for (const int i : best.inliers) sum += points.col(i);
  best.inlier_centroid = sum / static_cast<double>(best.inliers.size());
  return best;
}

}  // namespace cairn::perception
