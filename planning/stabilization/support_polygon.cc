#include <cairn/planning/stabilization/support_polygon.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace cairn::planning {

namespace {
double Cross(const Eigen::Vector2d& o, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return (a - o).x() * (b - o).y() - (a - o).y() * (b - o).x();
}

double SegmentDistance(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& p) {
  const Eigen::Vector2d d = b - a;
  const double length2 = d.squaredNorm();
  const double s = length2 > 0.0 ? std::clamp((p - a).dot(d) / length2, 0.0, 1.0) : 0.0;
  return (a + s * d - p).norm();
}
}  // namespace

std::vector<Eigen::Vector2d> SupportPolygon(const std::vector<multibody::Pose>& soles, double sole_length,
                                            double sole_width) {
  std::vector<Eigen::Vector2d> points;
  for (const multibody::Pose& X : soles) {
    const Eigen::Vector3d x_axis = X.rotation().col(0);
    const double yaw = std::atan2(x_axis.y(), x_axis.x());
    const Eigen::Vector2d forward(std::cos(yaw), std::sin(yaw)), left(-std::sin(yaw), std::cos(yaw));
    const Eigen::Vector2d c = X.translation().head<2>();
    for (double sx : {-0.5, 0.5}) {
      for (double sy : {-0.5, 0.5}) points.push_back(c + sx * sole_length * forward + sy * sole_width * left);
    }
  }
  if (points.size() < 3) return points;
  std::sort(points.begin(), points.end(), [](const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
    return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y());
  });
  std::vector<Eigen::Vector2d> hull(2 * points.size());
  std::size_t k = 0;
  for (const Eigen::Vector2d& p : points) {
    while (k >= 2 && Cross(hull[k - 2], hull[k - 1], p) <= 0.0) --k;
    hull[k++] = p;
  }
  for (std::size_t i = points.size() - 1, lower = k + 1; i > 0; --i) {
    const Eigen::Vector2d& p = points[i - 1];
    while (k >= lower && Cross(hull[k - 2], hull[k - 1], p) <= 0.0) --k;
    hull[k++] = p;
  }
  hull.resize(k - 1);
  return hull;
}

double SupportMargin(const std::vector<Eigen::Vector2d>& polygon, const Eigen::Vector2d& p) {
  if (polygon.empty()) return -std::numeric_limits<double>::infinity();
  double nearest = std::numeric_limits<double>::infinity();
  bool inside = polygon.size() >= 3;
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const Eigen::Vector2d& a = polygon[i];
    const Eigen::Vector2d& b = polygon[(i + 1) % polygon.size()];
    nearest = std::min(nearest, SegmentDistance(a, b, p));
    if (Cross(a, b, p) < 0.0) inside = false;
  }
  return inside ? nearest : -nearest;
}

}  // namespace cairn::planning
