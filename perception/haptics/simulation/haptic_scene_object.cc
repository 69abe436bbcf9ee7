#include "cairn/perception/haptics/simulation/haptic_scene_object.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <utility>

#include "cairn/common/number_text.h"

namespace cairn::perception {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// Smallest t > eps of |o + t d - c| = r (d unit).
double RaySphere(const Eigen::Vector3d& o, const Eigen::Vector3d& d, const Eigen::Vector3d& c, double r) {
  const Eigen::Vector3d oc = o - c;
  const double b = oc.dot(d);
  const double cc = oc.squaredNorm() - r * r;
  const double disc = b * b - cc;
  if (disc < 0.0) return kInf;
  const double s = std::sqrt(disc);
  const double t0 = -b - s;
  if (t0 > 1e-9) return t0;
  const double t1 = -b + s;
  return t1 > 1e-9 ? t1 : kInf;
}

double RayCapsule(const Eigen::Vector3d& o, const Eigen::Vector3d& d, const Eigen::Vector3d& a,
                  const Eigen::Vector3d& b, double r) {
  double best = std::min(RaySphere(o, d, a, r), RaySphere(o, d, b, r));
  const Eigen::Vector3d axis = b - a;
  const double length = axis.norm();
  if (length <= 0.0) return best;
  const Eigen::Vector3d u = axis / length;
  // The infinite cylinder, restricted to the segment's extent.
  const Eigen::Vector3d w = o - a;
  const Eigen::Vector3d dp = d - d.dot(u) * u;
  const Eigen::Vector3d wp = w - w.dot(u) * u;
  const double qa = dp.squaredNorm();
  if (qa < 1e-18) return best;
  const double qb = 2.0 * dp.dot(wp);
  const double qc = wp.squaredNorm() - r * r;
  const double disc = qb * qb - 4.0 * qa * qc;
  if (disc < 0.0) return best;
  const double s = std::sqrt(disc);
  for (const double t : {(-qb - s) / (2.0 * qa), (-qb + s) / (2.0 * qa)}) {
    if (t <= 1e-9 || t >= best) continue;
    const double along = (w + t * d).dot(u);
    if (along >= 0.0 && along <= length) best = t;
  }
  return best;
}

double RayBox(const Eigen::Vector3d& o, const Eigen::Vector3d& d, const Eigen::Vector3d& c,
              const Eigen::Vector3d& h) {
  double t0 = -kInf;
  double t1 = kInf;
  for (int i = 0; i < 3; ++i) {
    const double lo = c[i] - h[i] - o[i];
    const double hi = c[i] + h[i] - o[i];
    if (std::abs(d[i]) < 1e-15) {
      if (lo > 0.0 || hi < 0.0) return kInf;
      continue;
    }
    double a = lo / d[i];
    double b = hi / d[i];
    if (a > b) std::swap(a, b);
    t0 = std::max(t0, a);
    t1 = std::min(t1, b);
  }
  if (t0 > t1) return kInf;
  if (t0 > 1e-9) return t0;
  return t1 > 1e-9 ? t1 : kInf;
}

double SegmentDistance(const Eigen::Vector3d& p, const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  const Eigen::Vector3d ab = b - a;
  const double l2 = ab.squaredNorm();
  const double t = l2 > 0.0 ? std::clamp((p - a).dot(ab) / l2, 0.0, 1.0) : 0.0;
  return (p - (a + t * ab)).norm();
}

double PrimitiveDistance(const HapticPrimitive& q, const Eigen::Vector3d& p) {
  switch (q.shape) {
    case HapticPrimitive::Shape::kSphere:
      return (p - q.a).norm() - q.radius;
    case HapticPrimitive::Shape::kCapsule:
      return SegmentDistance(p, q.a, q.b) - q.radius;
    case HapticPrimitive::Shape::kBox: {
      const Eigen::Vector3d d = (p - q.a).cwiseAbs() - q.b;
      return d.cwiseMax(0.0).norm() + std::min(d.maxCoeff(), 0.0);
    }
  }
  return kInf;
}

}  // namespace

HapticSceneObject::HapticSceneObject(std::string name, std::vector<HapticPrimitive> primitives)
    : name_(std::move(name)), primitives_(std::move(primitives)) {
  if (primitives_.size() > static_cast<std::size_t>(kMaxPrimitives)) {
    throw std::invalid_argument("object '" + name_ + "' has " + FormatShort(primitives_.size()) +
                                " primitives; at most " + FormatShort(kMaxPrimitives) + " are allowed");
  }
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(kInf);
  Eigen::Vector3d hi = Eigen::Vector3d::Constant(-kInf);
  for (std::size_t i = 0; i < primitives_.size(); ++i) {
    const HapticPrimitive& q = primitives_[i];
    const bool box = q.shape == HapticPrimitive::Shape::kBox;
    if (!q.a.allFinite() || !q.b.allFinite() || !std::isfinite(q.radius) || (!box && !(q.radius > 0.0)) ||
        (box && !(q.b.minCoeff() > 0.0))) {
      throw std::invalid_argument("primitive " + FormatShort(i) + " of object '" + name_ +
                                  "' has a non-finite or non-positive size; radii and half extents must be > 0");
    }
    if (q.stiff) traversable_ = false;
    Eigen::Vector3d qlo;
    Eigen::Vector3d qhi;
    if (box) {
      qlo = q.a - q.b;
      qhi = q.a + q.b;
    } else {
      const Eigen::Vector3d end = q.shape == HapticPrimitive::Shape::kCapsule ? q.b : q.a;
      qlo = q.a.cwiseMin(end).array() - q.radius;
      qhi = q.a.cwiseMax(end).array() + q.radius;
    }
    lo = lo.cwiseMin(qlo);
    hi = hi.cwiseMax(qhi);
  }
  if (!primitives_.empty()) {
    bounding_center_ = 0.5 * (lo + hi);
    bounding_radius_ = 0.5 * (hi - lo).norm();
  }
}

HapticSceneObject HapticSceneObject::Translated(const Eigen::Vector3d& offset) const {
  std::vector<HapticPrimitive> moved = primitives_;
  for (HapticPrimitive& q : moved) {
    q.a += offset;
    if (q.shape == HapticPrimitive::Shape::kCapsule) q.b += offset;
  }
  return HapticSceneObject(name_, std::move(moved));
}

std::optional<double> HapticSceneObject::CastRay(const Eigen::Vector3d& origin, const Eigen::Vector3d& dir,
                                                 double max_t) const {
  if (primitives_.empty()) return std::nullopt;
  // Rays that miss the bounding sphere miss every primitive.
  const Eigen::Vector3d oc = origin - bounding_center_;
  const double b = oc.dot(dir);
  if (oc.squaredNorm() > bounding_radius_ * bounding_radius_ &&
      (b > 0.0 || b * b - oc.squaredNorm() + bounding_radius_ * bounding_radius_ < 0.0)) {
    return std::nullopt;
  }
  double best = kInf;
  for (const HapticPrimitive& q : primitives_) {
    double t = kInf;
    switch (q.shape) {
      case HapticPrimitive::Shape::kSphere: t = RaySphere(origin, dir, q.a, q.radius); break;
      case HapticPrimitive::Shape::kCapsule: t = RayCapsule(origin, dir, q.a, q.b, q.radius); break;
      case HapticPrimitive::Shape::kBox: t = RayBox(origin, dir, q.a, q.b); break;
    }
    best = std::min(best, t);
  }
  if (best <= max_t) return best;
  return std::nullopt;
}

double HapticSceneObject::StiffDistance(const Eigen::Vector3d& p) const {
  double best = kInf;
  for (const HapticPrimitive& q : primitives_) {
    if (q.stiff) best = std::min(best, PrimitiveDistance(q, p));
  }
  return best;
}

}  // namespace cairn::perception
