#include <cairn/multibody/shape_distance.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace cairn::multibody {
namespace {

double Clamp01(double x) { return std::min(1.0, std::max(0.0, x)); }

// Signed distance from a point (box frame) to a centred box with half extents h.
double BoxSdf(const Eigen::Vector3d& p, const Eigen::Vector3d& h) {
  const Eigen::Vector3d q = p.cwiseAbs() - h;
  return q.cwiseMax(0.0).norm() + std::min(q.maxCoeff(), 0.0);
}

}  // namespace

ShapeDistance Swapped(const ShapeDistance& d) {
  ShapeDistance out;
  out.distance = d.distance;
  out.p_A = d.p_B;
  out.p_B = d.p_A;
  out.normal = -d.normal;
  return out;
}

ShapeDistance SphereSphereDistance(const Eigen::Vector3d& center_A, double radius_A, const Eigen::Vector3d& center_B,
                                   double radius_B) {
  ShapeDistance out;
  const Eigen::Vector3d delta = center_B - center_A;
  const double norm = delta.norm();
  out.normal = norm > 1e-15 ? Eigen::Vector3d(delta / norm) : Eigen::Vector3d::UnitZ();
  out.distance = norm - radius_A - radius_B;
  out.p_A = center_A + radius_A * out.normal;
  out.p_B = center_B - radius_B * out.normal;
  return out;
}

void ClosestSegmentParameters(const Eigen::Vector3d& p1, const Eigen::Vector3d& q1, const Eigen::Vector3d& p2,
                              const Eigen::Vector3d& q2, double* s, double* t) {
  // Ericson, Real-Time Collision Detection, 5.1.9, with the degenerate (point) cases.
  const Eigen::Vector3d d1 = q1 - p1, d2 = q2 - p2, r = p1 - p2;
  const double a = d1.squaredNorm(), e = d2.squaredNorm(), f = d2.dot(r);
  const double eps = 1e-30;
  if (a <= eps && e <= eps) {
    *s = *t = 0.0;
    return;
  }
  if (a <= eps) {
    *s = 0.0;
    *t = Clamp01(f / e);
    return;
  }
  const double c = d1.dot(r);
  if (e <= eps) {
    *t = 0.0;
    *s = Clamp01(-c / a);
    return;
  }
  const double b = d1.dot(d2);
  const double denom = a * e - b * b;
  double sv = denom > 1e-14 * a * e ? Clamp01((b * f - c * e) / denom) : 0.0;
  double tv = (b * sv + f) / e;
  if (tv < 0.0) {
    tv = 0.0;
    sv = Clamp01(-c / a);
  } else if (tv > 1.0) {
    tv = 1.0;
    sv = Clamp01((b - c) / a);
  }
  *s = sv;
  *t = tv;
}

ShapeDistance SphereCapsuleDistance(const Eigen::Vector3d& center_A, double radius_A, const Eigen::Vector3d& a_B,
                                    const Eigen::Vector3d& b_B, double radius_B) {
  const Eigen::Vector3d axis = b_B - a_B;
  const double length2 = axis.squaredNorm();
  const double t = length2 > 0.0 ? Clamp01((center_A - a_B).dot(axis) / length2) : 0.0;
  return SphereSphereDistance(center_A, radius_A, a_B + t * axis, radius_B);
}

ShapeDistance CapsuleCapsuleDistance(const Eigen::Vector3d& a_A, const Eigen::Vector3d& b_A, double radius_A,
                                     const Eigen::Vector3d& a_B, const Eigen::Vector3d& b_B, double radius_B) {
  double s = 0.0, t = 0.0;
  ClosestSegmentParameters(a_A, b_A, a_B, b_B, &s, &t);
  return SphereSphereDistance(a_A + s * (b_A - a_A), radius_A, a_B + t * (b_B - a_B), radius_B);
}

ShapeDistance BoxSphereDistance(const Pose& X_WA, const Eigen::Vector3d& size_A, const Eigen::Vector3d& center_B,
                                double radius_B) {
  const Eigen::Vector3d h = 0.5 * size_A;
  const Eigen::Vector3d c = X_WA.rotation().transpose() * (center_B - X_WA.translation());
  const Eigen::Vector3d clamped = c.cwiseMax(-h).cwiseMin(h);
  Eigen::Vector3d surface, normal;
  double sdf;
  if (clamped != c) {
    const Eigen::Vector3d delta = c - clamped;
    sdf = delta.norm();
    normal = delta / sdf;
    surface = clamped;
  } else {
    // Inside: leave through the nearest face.
    const Eigen::Vector3d depth = h - c.cwiseAbs();
    int k = 0;
    depth.minCoeff(&k);
    normal = Eigen::Vector3d::Zero();
    normal[k] = c[k] >= 0.0 ? 1.0 : -1.0;
    surface = c;
    surface[k] = normal[k] * h[k];
    sdf = -depth[k];
  }
  ShapeDistance out;
  out.normal = X_WA.rotation() * normal;
  out.p_A = X_WA * surface;
  out.distance = sdf - radius_B;
  out.p_B = center_B - radius_B * out.normal;
  return out;
}

ShapeDistance BoxCapsuleDistance(const Pose& X_WA, const Eigen::Vector3d& size_A, const Eigen::Vector3d& a_B,
                                 const Eigen::Vector3d& b_B, double radius_B) {
  const Eigen::Vector3d h = 0.5 * size_A;
  const Eigen::Vector3d a = X_WA.rotation().transpose() * (a_B - X_WA.translation());
  const Eigen::Vector3d b = X_WA.rotation().transpose() * (b_B - X_WA.translation());
  // Golden-section search of the convex function t -> sdf(a + t (b - a)) on [0, 1].
  const double ratio = 0.5 * (std::sqrt(5.0) - 1.0);
  double lo = 0.0, hi = 1.0;
  double x1 = hi - ratio * (hi - lo), x2 = lo + ratio * (hi - lo);
  double f1 = BoxSdf(a + x1 * (b - a), h), f2 = BoxSdf(a + x2 * (b - a), h);
  while (hi - lo > 1e-10) {
    if (f1 <= f2) {
      hi = x2;
      x2 = x1;
      f2 = f1;
      x1 = hi - ratio * (hi - lo);
      f1 = BoxSdf(a + x1 * (b - a), h);
    } else {
      lo = x1;
      x1 = x2;
      f1 = f2;
      x2 = lo + ratio * (hi - lo);
      f2 = BoxSdf(a + x2 * (b - a), h);
    }
  }
  double t = 0.5 * (lo + hi);
  // The minimum may sit at an end point the bracketing only approaches.
  if (BoxSdf(a, h) <= BoxSdf(a + t * (b - a), h)) t = 0.0;
  if (BoxSdf(b, h) < BoxSdf(a + t * (b - a), h)) t = 1.0;
  return BoxSphereDistance(X_WA, size_A, a_B + t * (b_B - a_B), radius_B);
}

namespace {

// Corner k (bits select the sign per axis) of a box.
Eigen::Vector3d Corner(const Pose& X, const Eigen::Vector3d& h, int k) {
  return X * Eigen::Vector3d((k & 1) ? h.x() : -h.x(), (k & 2) ? h.y() : -h.y(), (k & 4) ? h.z() : -h.z());
}

// Half-length of a box's projection onto unit axis L.
double ProjectedRadius(const Pose& X, const Eigen::Vector3d& h, const Eigen::Vector3d& L) {
  return h.x() * std::abs(X.rotation().col(0).dot(L)) + h.y() * std::abs(X.rotation().col(1).dot(L)) +
         h.z() * std::abs(X.rotation().col(2).dot(L));
}

}  // namespace

ShapeDistance BoxBoxDistance(const Pose& X_WA, const Eigen::Vector3d& size_A, const Pose& X_WB,
                             const Eigen::Vector3d& size_B, double early_out) {
  const Eigen::Vector3d hA = 0.5 * size_A, hB = 0.5 * size_B;
  const Eigen::Vector3d delta = X_WB.translation() - X_WA.translation();
  // Separating axis test over the 15 candidate axes, remembering the axis of least overlap.
  double largest_gap = 0.0;
  double least_overlap = std::numeric_limits<double>::infinity();
  Eigen::Vector3d least_axis = Eigen::Vector3d::UnitZ();
  auto test_axis = [&](Eigen::Vector3d L) {
    const double norm = L.norm();
    if (norm < 1e-9) return;
    L /= norm;
    const double projected = delta.dot(L);
    const double overlap = ProjectedRadius(X_WA, hA, L) + ProjectedRadius(X_WB, hB, L) - std::abs(projected);
    largest_gap = std::max(largest_gap, -overlap);
    if (overlap < least_overlap) {
      least_overlap = overlap;
      least_axis = projected >= 0.0 ? L : Eigen::Vector3d(-L);
    }
  };
  for (int i = 0; i < 3; ++i) test_axis(X_WA.rotation().col(i));
  for (int i = 0; i < 3; ++i) test_axis(X_WB.rotation().col(i));
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) test_axis(X_WA.rotation().col(i).cross(X_WB.rotation().col(j)));
  }
  Eigen::Vector3d corners_A[8], corners_B[8];
  for (int k = 0; k < 8; ++k) {
    corners_A[k] = Corner(X_WA, hA, k);
    corners_B[k] = Corner(X_WB, hB, k);
  }
  ShapeDistance best;
  if (least_overlap >= 0.0) {
    // Overlapping. The support vertices: A's furthest along n and B's furthest along -n. The signed distance is
    // the overlap along n, and with these points its derivative is n . (v_B(p_B) - v_A(p_A)).
    const Eigen::Vector3d& n = least_axis;
    int support_A = 0, support_B = 0;
    for (int k = 1; k < 8; ++k) {
      if (corners_A[k].dot(n) > corners_A[support_A].dot(n)) support_A = k;
      if (corners_B[k].dot(n) < corners_B[support_B].dot(n)) support_B = k;
    }
    best.distance = -least_overlap;
    best.normal = n;
    best.p_A = corners_A[support_A];
    best.p_B = corners_B[support_B];
    return best;
  }
  if (largest_gap >= early_out) {
    // A separating gap is a lower bound of the distance; the caller does not need more.
    best.distance = largest_gap;
    best.normal = least_axis;
    best.p_A = X_WA.translation();
    best.p_B = X_WA.translation() + largest_gap * least_axis;
    return best;
  }
  best.distance = std::numeric_limits<double>::infinity();
  for (int k = 0; k < 8; ++k) {
    const ShapeDistance a_vertex = Swapped(BoxSphereDistance(X_WB, size_B, corners_A[k], 0.0));
    if (a_vertex.distance < best.distance) best = a_vertex;
    const ShapeDistance b_vertex = BoxSphereDistance(X_WA, size_A, corners_B[k], 0.0);
    if (b_vertex.distance < best.distance) best = b_vertex;
  }
  // Edges: for each axis, the four edges parallel to it join corners differing only in that axis' bit. An edge
  // farther from the other box's bounding sphere than the best distance so far cannot hold the closest point.
  const double radius_A = hA.norm(), radius_B = hB.norm();
  auto segment_point_distance = [](const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& p) {
    const Eigen::Vector3d ab = b - a;
    const double t = Clamp01((p - a).dot(ab) / ab.squaredNorm());
    return (a + t * ab - p).norm();
  };
  for (int axis_a = 0; axis_a < 3; ++axis_a) {
    for (int ka = 0; ka < 8; ++ka) {
      if (ka & (1 << axis_a)) continue;
      const Eigen::Vector3d& a0 = corners_A[ka];
      const Eigen::Vector3d& a1 = corners_A[ka | (1 << axis_a)];
      if (segment_point_distance(a0, a1, X_WB.translation()) - radius_B >= best.distance) continue;
      for (int axis_b = 0; axis_b < 3; ++axis_b) {
        for (int kb = 0; kb < 8; ++kb) {
          if (kb & (1 << axis_b)) continue;
          const Eigen::Vector3d& b0 = corners_B[kb];
          const Eigen::Vector3d& b1 = corners_B[kb | (1 << axis_b)];
          if (segment_point_distance(b0, b1, X_WA.translation()) - radius_A >= best.distance) continue;
          double s = 0.0, t = 0.0;
          ClosestSegmentParameters(a0, a1, b0, b1, &s, &t);
          const Eigen::Vector3d pa = a0 + s * (a1 - a0), pb = b0 + t * (b1 - b0);
          if ((pb - pa).norm() < best.distance) best = SphereSphereDistance(pa, 0.0, pb, 0.0);
        }
      }
    }
  }
  return best;
}

}  // namespace cairn::multibody
