#include "cairn/perception/synthetic/synthetic_stereo_scene.h"

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>

#include "cairn/common/cairn_assert.h"

namespace cairn::perception {

int SyntheticStereoScene::AddPlane(const Eigen::Vector3d& point, const Eigen::Vector3d& normal,
                                   const ProceduralTexture& texture, int label) {
  if (!(normal.norm() > 0.0)) {
    throw std::invalid_argument("SyntheticStereoScene::AddPlane: the normal is zero; give the plane's normal direction");
  }
  const Eigen::Vector3d z = normal.normalized();
  const Eigen::Vector3d helper = std::abs(z.x()) < 0.9 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitY();
  const Eigen::Vector3d x = (helper - helper.dot(z) * z).normalized();
  Eigen::Isometry3d frame = Eigen::Isometry3d::Identity();
  frame.linear().col(0) = x;
  frame.linear().col(1) = z.cross(x);
  frame.linear().col(2) = z;
  frame.translation() = point;
  objects_.push_back(Object{false, frame, frame.inverse(), Eigen::Vector3d::Zero(), texture, label});
  return num_objects() - 1;
}

int SyntheticStereoScene::AddBox(const Eigen::Isometry3d& X_WB, const Eigen::Vector3d& half_extents,
                                 const ProceduralTexture& texture, int label) {
  for (int i = 0; i < 3; ++i) {
    if (!(half_extents[i] > 0.0)) {
      throw std::invalid_argument("SyntheticStereoScene::AddBox: half extent " + std::to_string(i) + " is " +
                                  std::to_string(half_extents[i]) + "; every half extent must be positive");
    }
  }
  objects_.push_back(Object{true, X_WB, X_WB.inverse(), half_extents, texture, label});
  return num_objects() - 1;
}

std::optional<SyntheticStereoScene::Hit> SyntheticStereoScene::Intersect(const Eigen::Vector3d& origin,
                                                                        const Eigen::Vector3d& direction) const {
  constexpr double kEps = 1e-9;
  std::optional<Hit> best;
  double best_u = 0.0;
  double best_v = 0.0;
  for (int i = 0; i < num_objects(); ++i) {
    const Object& object = objects_[i];
    const Eigen::Vector3d o = object.X_BW * origin;
    const Eigen::Vector3d d = object.X_WB.linear().transpose() * direction;
    double t = std::numeric_limits<double>::infinity();
    double u = 0.0;
    double v = 0.0;
    if (!object.is_box) {
      if (std::abs(d.z()) < kEps) continue;
      t = -o.z() / d.z();
      if (!(t > kEps)) continue;
      u = o.x() + t * d.x();
      v = o.y() + t * d.y();
    } else {
      // Slab test in the box frame.
      double t_near = -std::numeric_limits<double>::infinity();
      double t_far = std::numeric_limits<double>::infinity();
      int axis = -1;
      bool miss = false;
      for (int a = 0; a < 3; ++a) {
        const double h = object.half_extents[a];
        if (std::abs(d[a]) < kEps) {
          if (std::abs(o[a]) > h) miss = true;
          continue;
        }
        double t0 = (-h - o[a]) / d[a];
        double t1 = (h - o[a]) / d[a];
        if (t0 > t1) std::swap(t0, t1);
        if (t0 > t_near) {
          t_near = t0;
          axis = a;
        }
        t_far = std::min(t_far, t1);
      }
      if (miss || t_near > t_far || !(t_near > kEps) || axis < 0) continue;
      t = t_near;
      const Eigen::Vector3d p = o + t * d;
      u = p[(axis + 1) % 3];
      v = p[(axis + 2) % 3];
    }
    if (!best || t < best->t) {
      best = Hit{t, i, object.label, 0.0};
      best_u = u;
      best_v = v;
    }
  }
  // The texture is evaluated once, for the nearest surface only.
  if (best) best->intensity = objects_[best->object].texture.Evaluate(best_u, best_v);
  return best;
}

bool SyntheticStereoScene::Occupies(const Eigen::Vector3d& p_W, double tolerance) const {
  for (const Object& object : objects_) {
    const Eigen::Vector3d p = object.X_BW * p_W;
    if (object.is_box) {
      if ((p.cwiseAbs() - object.half_extents).maxCoeff() <= tolerance) return true;
    } else if (std::abs(p.z()) <= tolerance) {
      return true;
    }
  }
  return false;
}

bool SyntheticStereoScene::OccupiesCube(const Eigen::Vector3d& center, double size) const {
  // Exact overlap by the separating-axis theorem: the cube (axis-aligned, half side h) and an object overlap
  // unless their projections on some axis are disjoint. A lattice of sample points with a tolerance would
  // inflate thin objects by the tolerance and make ground truth depend on the grid's phase.
  const double h = 0.5 * size;
  for (const Object& object : objects_) {
    const Eigen::Vector3d offset = object.X_WB.translation() - center;
    const Eigen::Matrix3d R = object.X_WB.linear();
    if (!object.is_box) {
      const Eigen::Vector3d n = R.col(2);
      if (std::abs(n.dot(offset)) <= h * n.cwiseAbs().sum()) return true;
      continue;
    }
    const Eigen::Vector3d& e = object.half_extents;
    // Radius of the box's projection on a world axis `axis`.
    auto box_radius = [&](const Eigen::Vector3d& axis) {
      return e.x() * std::abs(R.col(0).dot(axis)) + e.y() * std::abs(R.col(1).dot(axis)) +
             e.z() * std::abs(R.col(2).dot(axis));
    };
    auto separated = [&](const Eigen::Vector3d& axis) {
      const double norm = axis.norm();
      if (norm < 1e-12) return false;  // parallel edges: the face axes already cover this case
      return std::abs(axis.dot(offset)) > h * axis.cwiseAbs().sum() + box_radius(axis) + 1e-12 * norm;
    };
    bool apart = false;
    for (int a = 0; a < 3 && !apart; ++a) {
      apart = separated(Eigen::Vector3d::Unit(a)) || separated(R.col(a));
      for (int b = 0; b < 3 && !apart; ++b) apart = separated(Eigen::Vector3d::Unit(a).cross(R.col(b)));
    }
    if (!apart) return true;
  }
  return false;
}

void SyntheticStereoScene::SetColourTexture(int object, ColourTexture texture) {
  if (object < 0 || object >= num_objects()) {
    throw std::invalid_argument("SyntheticStereoScene::SetColourTexture: object " + std::to_string(object) +
                                " does not exist; the scene has " + std::to_string(num_objects()) +
                                " objects (use the index AddPlane/AddBox returned)");
  }
  if (!texture) {
    throw std::invalid_argument("SyntheticStereoScene::SetColourTexture: the texture of object " +
                                std::to_string(object) + " is an empty function");
  }
  if (colour_textures_.size() < objects_.size()) colour_textures_.resize(objects_.size());
  if (!colour_textures_[object]) ++num_colour_textures_;
  colour_textures_[object] = std::move(texture);
}

Eigen::Vector3d SyntheticStereoScene::ColourOf(const Eigen::Vector3d& origin, const Eigen::Vector3d& direction,
                                               const Hit& hit) const {
  CAIRN_CHECK(hit.object >= 0 && hit.object < num_objects());
  const bool coloured = hit.object < static_cast<int>(colour_textures_.size()) && colour_textures_[hit.object];
  if (!coloured) return Eigen::Vector3d::Constant(hit.intensity);
  // The texture coordinates Intersect() used, recomputed by the same operations (so bit for bit): a plane's
  // in-plane axes; for a box, the two axes of the face the ray enters through, the slab with the latest entry.
  const Object& object = objects_[hit.object];
  const Eigen::Vector3d o = object.X_BW * origin;
  const Eigen::Vector3d d = object.X_WB.linear().transpose() * direction;
  const Eigen::Vector3d p = o + hit.t * d;
  if (!object.is_box) return colour_textures_[hit.object](p.x(), p.y());
  double t_near = -std::numeric_limits<double>::infinity();
  int axis = 0;
  for (int a = 0; a < 3; ++a) {
    if (std::abs(d[a]) < 1e-9) continue;
    const double h = object.half_extents[a];
    const double t0 = std::min((-h - o[a]) / d[a], (h - o[a]) / d[a]);
    if (t0 > t_near) {
      t_near = t0;
      axis = a;
    }
  }
  return colour_textures_[hit.object](p[(axis + 1) % 3], p[(axis + 2) % 3]);
}

}  // namespace cairn::perception
