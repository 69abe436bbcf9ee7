#include <cairn/multibody/collision_world.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <set>
#include <sstream>
#include <stdexcept>
#include <system_error>

#include <fcl/geometry/bvh/BVH_model.h>
#include <fcl/geometry/shape/box.h>
#include <fcl/geometry/shape/capsule.h>
#include <fcl/geometry/shape/cylinder.h>
#include <fcl/geometry/shape/sphere.h>
#include <fcl/math/bv/OBBRSS.h>
#include <fcl/narrowphase/distance.h>

#include <cairn/common/number_text.h>
#include <cairn/common/text_suggestions.h>
#include <cairn/multibody/joint_motion.h>

namespace cairn::multibody {
namespace {

using Mesh = fcl::BVHModel<fcl::OBBRSSd>;

// Reads binary or ASCII STL triangles, scaled per axis.
std::shared_ptr<Mesh> ReadStl(const std::string& path, const Eigen::Vector3d& scale, const std::string& owner,
                              double* extent) {
  std::error_code error;
  if (std::filesystem::is_directory(path, error)) {
    throw std::invalid_argument(owner + ": mesh '" + path + "' is a directory, expected an STL file");
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::invalid_argument(owner + ": cannot open mesh '" + path + "'");
  // Read at most one byte past the limit, so that a huge or endless file is refused without reading it all.
  std::string bytes;
  char buffer[1 << 16];
  while (in && bytes.size() <= kMaxMeshBytes) {
    in.read(buffer, sizeof(buffer));
    bytes.append(buffer, static_cast<std::size_t>(in.gcount()));
  }
  if (bytes.size() > kMaxMeshBytes) {
    throw std::invalid_argument(owner + ": mesh '" + path + "' is larger than " + std::to_string(kMaxMeshBytes) +
                                " bytes (256 MiB, kMaxMeshBytes); simplify the mesh for collision queries");
  }
  std::vector<fcl::Vector3d> vertices;
  std::vector<fcl::Triangle> triangles;
  auto add = [&](const Eigen::Vector3d& v) {
    vertices.push_back(v.cwiseProduct(scale));
    *extent = std::max(*extent, vertices.back().norm());
  };
  bool binary = false;
  if (bytes.size() >= 84) {
    std::uint32_t count = 0;
    std::memcpy(&count, bytes.data() + 80, 4);
    binary = bytes.size() == 84 + 50 * static_cast<std::size_t>(count);
    if (binary) {
      for (std::uint32_t t = 0; t < count; ++t) {
        const char* record = bytes.data() + 84 + 50 * static_cast<std::size_t>(t) + 12;
        for (int k = 0; k < 3; ++k) {
          float xyz[3];
          std::memcpy(xyz, record + 12 * k, 12);
          add(Eigen::Vector3d(xyz[0], xyz[1], xyz[2]));
        }
      }
    }
  }
  if (!binary) {
    if (bytes.compare(0, 5, "solid") != 0) {
      throw std::invalid_argument(owner + ": mesh '" + path +
                                  "' is neither binary nor ASCII STL; convert it to STL for collision queries");
    }
    std::istringstream text(bytes);
    std::string word;
    while (text >> word) {
      if (word != "vertex") continue;
      Eigen::Vector3d v;
      if (!(text >> v.x() >> v.y() >> v.z())) {
        throw std::invalid_argument(owner + ": mesh '" + path + "': vertex " + std::to_string(vertices.size()) +
                                    " does not hold three numbers; the ASCII STL file is corrupt");
      }
      add(v);
    }
  }
  for (std::size_t i = 0; i < vertices.size(); ++i) {
    if (!vertices[i].allFinite()) {
      throw std::invalid_argument(owner + ": mesh '" + path + "': vertex " + std::to_string(i) +
                                  " is not finite (NaN or infinite); the STL file is corrupt");
    }
  }
  if (vertices.empty() || vertices.size() % 3 != 0) {
    throw std::invalid_argument(owner + ": mesh '" + path + "' holds no triangles");
  }
  for (std::size_t i = 0; i < vertices.size(); i += 3) triangles.emplace_back(i, i + 1, i + 2);
  auto mesh = std::make_shared<Mesh>();
  mesh->beginModel();
  mesh->addSubModel(vertices, triangles);
  mesh->endModel();
  return mesh;
}

fcl::Transform3d ToFcl(const Pose& X) {
  fcl::Transform3d T = fcl::Transform3d::Identity();
  T.linear() = X.rotation();
  T.translation() = X.translation();
  return T;
}

}  // namespace

struct CollisionWorld::Impl {
  struct Item {
    std::string name;
    int body = -1;
    Geometry geometry;
    Pose X_WG;
    bool is_points = false;
    Eigen::Matrix3Xd points;
    double point_radius = 0.0;
    bool is_height_field = false;
    Eigen::MatrixXd heights;  // heights(i, j) for the cell at x index i, y index j; NaN = unknown
    double cell_size = 0.0;
    Eigen::Vector2d origin = Eigen::Vector2d::Zero();
    double bottom = 0.0;
    std::shared_ptr<fcl::CollisionGeometryd> fcl;
    double extent = 0.0;  // radius of a ball about the geometry origin enclosing the shape
    Eigen::Vector3d box_min = Eigen::Vector3d::Zero();
    Eigen::Vector3d box_max = Eigen::Vector3d::Zero();
  };

  std::vector<Item> items;
  std::vector<int> parents;
  std::vector<std::string> body_names;
  std::set<std::pair<int, int>> excluded_bodies;
  std::set<std::pair<int, int>> excluded_geometries;

  void UpdateBox(Item& item) {
    if (item.is_height_field) {
      const double top = item.heights.array().isNaN().select(item.bottom, item.heights.array()).maxCoeff();
      item.box_min = Eigen::Vector3d(item.origin.x(), item.origin.y(), item.bottom);
      item.box_max = Eigen::Vector3d(item.origin.x() + item.cell_size * static_cast<double>(item.heights.rows()),
                                     item.origin.y() + item.cell_size * static_cast<double>(item.heights.cols()), top);
    } else if (item.is_points) {
      item.box_min = item.points.rowwise().minCoeff().array() - item.point_radius;
      item.box_max = item.points.rowwise().maxCoeff().array() + item.point_radius;
    } else {
      // Tight boxes for the closed-form shapes (a large ground box would otherwise pass every test).
      Eigen::Vector3d half = Eigen::Vector3d::Constant(item.extent);
      const Eigen::Matrix3d abs_R = item.X_WG.rotation().cwiseAbs();
      if (item.geometry.type == GeometryType::kBox) {
        half = abs_R * (0.5 * item.geometry.size);
      } else if (item.geometry.type == GeometryType::kCapsule) {
        half = abs_R.col(2) * (0.5 * item.geometry.length) + Eigen::Vector3d::Constant(item.geometry.radius);
      }
      item.box_min = item.X_WG.translation() - half;
      item.box_max = item.X_WG.translation() + half;
    }
  }

  // checked[a * n + b]: whether the pair passes the filters; rebuilt whenever geometry or filters change so that
  // the query loop does no set lookups.
  std::vector<char> checked;

  void RebuildFilter() {
    const std::size_t n = items.size();
    checked.assign(n * n, 0);
    for (std::size_t a = 0; a < n; ++a) {
      for (std::size_t b = 0; b < n; ++b) {
        checked[a * n + b] = ComputeChecked(static_cast<int>(a), static_cast<int>(b)) ? 1 : 0;
      }
    }
  }

  bool Checked(int a, int b) const {
    return checked[static_cast<std::size_t>(a) * items.size() + static_cast<std::size_t>(b)] != 0;
  }

  int Add(Item item) {
    if (item.name.empty()) throw std::invalid_argument("CollisionWorld: environment geometry needs a name");
    for (const Item& other : items) {
      if (other.name == item.name) {
        throw std::invalid_argument("CollisionWorld: geometry name '" + item.name +
                                    "' is already used; give each geometry a unique name");
      }
    }
    UpdateBox(item);
    items.push_back(std::move(item));
    RebuildFilter();
    return static_cast<int>(items.size()) - 1;
  }

  bool ComputeChecked(int a, int b) const {
    if (a == b) return false;
    const Item& A = items[static_cast<std::size_t>(a)];
    const Item& B = items[static_cast<std::size_t>(b)];
    if (A.body < 0 && B.body < 0) return false;
    if (A.body >= 0 && B.body >= 0) {
      if (A.body == B.body) return false;
      if (parents[static_cast<std::size_t>(A.body)] == B.body || parents[static_cast<std::size_t>(B.body)] == A.body) {
        return false;
      }
      if (excluded_bodies.count(std::minmax(A.body, B.body)) > 0) return false;
    }
    return excluded_geometries.count(std::minmax(a, b)) == 0;
  }

  static bool ClosedFormShape(const Item& item) {
    return !item.is_points &&
           (item.geometry.type == GeometryType::kSphere || item.geometry.type == GeometryType::kCapsule ||
            item.geometry.type == GeometryType::kBox);
  }

  static void CapsuleEnds(const Item& item, Eigen::Vector3d* a, Eigen::Vector3d* b) {
    const Eigen::Vector3d half(0.0, 0.0, 0.5 * item.geometry.length);
    *a = item.X_WG * (-half);
    *b = item.X_WG * half;
  }

  // Closed form for sphere/capsule/box pairs except box-box; false if the pair needs FCL.
  // `early_out`: box pairs separated by more than this may return a lower bound instead of the exact distance.
  static bool ClosedForm(const Item& A, const Item& B, ShapeDistance* out,
                         double early_out = std::numeric_limits<double>::infinity()) {
    if (!ClosedFormShape(A) || !ClosedFormShape(B)) return false;
    const GeometryType ta = A.geometry.type, tb = B.geometry.type;
    if (ta == GeometryType::kBox && tb == GeometryType::kBox) {
      *out = BoxBoxDistance(A.X_WG, A.geometry.size, B.X_WG, B.geometry.size, early_out);
      return true;
    }
    if (tb == GeometryType::kBox) {
      if (!ClosedForm(B, A, out, early_out)) return false;
      *out = Swapped(*out);
      return true;
    }
    Eigen::Vector3d b0, b1;
    if (tb == GeometryType::kCapsule) CapsuleEnds(B, &b0, &b1);
    if (ta == GeometryType::kBox) {
      *out = tb == GeometryType::kSphere
                 ? BoxSphereDistance(A.X_WG, A.geometry.size, B.X_WG.translation(), B.geometry.radius)
                 : BoxCapsuleDistance(A.X_WG, A.geometry.size, b0, b1, B.geometry.radius);
      return true;
    }
    if (ta == GeometryType::kSphere) {
      *out =
          tb == GeometryType::kSphere
              ? SphereSphereDistance(A.X_WG.translation(), A.geometry.radius, B.X_WG.translation(), B.geometry.radius)
              : SphereCapsuleDistance(A.X_WG.translation(), A.geometry.radius, b0, b1, B.geometry.radius);
      return true;
    }
    Eigen::Vector3d a0, a1;
    CapsuleEnds(A, &a0, &a1);
    *out = tb == GeometryType::kSphere
               ? Swapped(SphereCapsuleDistance(B.X_WG.translation(), B.geometry.radius, a0, a1, A.geometry.radius))
               : CapsuleCapsuleDistance(a0, a1, A.geometry.radius, b0, b1, B.geometry.radius);
    return true;
  }

  static ShapeDistance Fcl(const std::shared_ptr<fcl::CollisionGeometryd>& ga, const Pose& Xa,
                           const std::shared_ptr<fcl::CollisionGeometryd>& gb, const Pose& Xb, bool meshes) {
    fcl::CollisionObjectd oa(ga, ToFcl(Xa));
    fcl::CollisionObjectd ob(gb, ToFcl(Xb));
    fcl::DistanceRequestd request;
    request.enable_nearest_points = true;
    request.enable_signed_distance = !meshes;
    request.gjk_solver_type = fcl::GST_LIBCCD;
    fcl::DistanceResultd result;
    fcl::distance(&oa, &ob, request, result);
    ShapeDistance out;
    out.distance = meshes ? std::max(0.0, result.min_distance) : result.min_distance;
    out.p_A = result.nearest_points[0];
    out.p_B = result.nearest_points[1];
    const Eigen::Vector3d delta = out.p_B - out.p_A;
    if (std::abs(out.distance) > 1e-12 && delta.norm() > 1e-12) {
      out.normal = delta / out.distance;
      out.normal.normalize();
    } else {
      const Eigen::Vector3d centers = Xb.translation() - Xa.translation();
      out.normal = centers.norm() > 1e-12 ? Eigen::Vector3d(centers.normalized()) : Eigen::Vector3d::UnitZ();
    }
    return out;
  }

  static bool IsMesh(const Item& item) { return !item.is_points && item.geometry.type == GeometryType::kMesh; }

  // Points of A (inflated spheres) against shape B: the closest point decides.
  ShapeDistance PointsDistance(const Item& A, const Item& B) const {
    ShapeDistance best;
    best.distance = std::numeric_limits<double>::infinity();
    // Each point is a sphere of the set's radius (0 is fine for the closed forms).
    Item sphere;
    sphere.geometry.type = GeometryType::kSphere;
    sphere.geometry.radius = A.point_radius;
    std::shared_ptr<fcl::CollisionGeometryd> fcl_sphere;
    for (Eigen::Index k = 0; k < A.points.cols(); ++k) {
      const Eigen::Vector3d p = A.points.col(k);
      // Skip points that cannot beat the best distance found so far.
      const double lower_bound = (p - B.X_WG.translation()).norm() - B.extent - A.point_radius;
      if (lower_bound >= best.distance) continue;
      sphere.X_WG = Pose(Eigen::Matrix3d::Identity(), p);
      ShapeDistance d;
      if (!ClosedForm(sphere, B, &d)) {
        d = Fcl(SphereGeometry(&fcl_sphere, A.point_radius), sphere.X_WG, B.fcl, B.X_WG, IsMesh(B));
      }
      if (d.distance < best.distance) best = d;
    }
    return best;
  }

  static const std::shared_ptr<fcl::CollisionGeometryd>& SphereGeometry(std::shared_ptr<fcl::CollisionGeometryd>* cache,
                                                                        double radius) {
    if (!*cache) *cache = std::make_shared<fcl::Sphered>(std::max(radius, 1e-9));
    return *cache;
  }

  // Shape A against the height field B, a union of vertical boxes (one per known cell, from `bottom` up to the
  // cell's height): the closest column decides, and columns that cannot beat it are skipped by a bound.
  ShapeDistance HeightFieldDistance(const Item& A, const Item& B) const {
    ShapeDistance best;
    best.distance = std::numeric_limits<double>::infinity();
    Item column;
    column.geometry.type = GeometryType::kBox;
    const Eigen::Vector3d c = A.is_points ? Eigen::Vector3d::Zero() : A.X_WG.translation();
    for (Eigen::Index i = 0; i < B.heights.rows(); ++i) {
      for (Eigen::Index j = 0; j < B.heights.cols(); ++j) {
        const double top = B.heights(i, j);
        if (std::isnan(top) || top <= B.bottom) continue;
        const Eigen::Vector3d lo(B.origin.x() + B.cell_size * static_cast<double>(i),
                                 B.origin.y() + B.cell_size * static_cast<double>(j), B.bottom);
        const Eigen::Vector3d hi(lo.x() + B.cell_size, lo.y() + B.cell_size, top);
        const double lower_bound = (c - c.cwiseMax(lo).cwiseMin(hi)).norm() - A.extent;
        if (lower_bound >= best.distance) continue;
        column.geometry.size = hi - lo;
        column.X_WG = Pose(Eigen::Matrix3d::Identity(), 0.5 * (lo + hi));
        column.extent = 0.5 * column.geometry.size.norm();
        ShapeDistance d;
        if (!ClosedForm(A, column, &d, best.distance)) {
          column.fcl = std::make_shared<fcl::Boxd>(column.geometry.size);
          d = Fcl(A.fcl, A.X_WG, column.fcl, column.X_WG, IsMesh(A));
        }
        if (d.distance < best.distance) best = d;
      }
    }
    return best;
  }

  ShapeDistance Distance(int a, int b, double early_out = std::numeric_limits<double>::infinity()) const {
    const Item& A = items[static_cast<std::size_t>(a)];
    const Item& B = items[static_cast<std::size_t>(b)];
    if ((A.is_points || A.is_height_field) && (B.is_points || B.is_height_field)) {
      throw std::invalid_argument("CollisionWorld: distance between environment point sets or height fields ('" +
                                  A.name + "', '" + B.name + "') is not supported; query them against robot geometry");
    }
    if (B.is_height_field) return HeightFieldDistance(A, B);
    if (A.is_height_field) return Swapped(HeightFieldDistance(B, A));
    if (A.is_points && B.is_points) {
      throw std::invalid_argument("CollisionWorld: distance between two point sets ('" + A.name + "', '" + B.name +
                                  "') is not supported; query points against robot geometry");
    }
    if (A.is_points) return PointsDistance(A, B);
    if (B.is_points) return Swapped(PointsDistance(B, A));
    ShapeDistance out;
    if (ClosedForm(A, B, &out, early_out)) return out;
    return Fcl(A.fcl, A.X_WG, B.fcl, B.X_WG, IsMesh(A) || IsMesh(B));
  }

  // FCL geometry and enclosing radius for a shape.
  void Prepare(Item& item, const std::string& owner) {
    const Geometry& g = item.geometry;
    switch (g.type) {
      case GeometryType::kBox:
        item.fcl = std::make_shared<fcl::Boxd>(g.size);
        item.extent = 0.5 * g.size.norm();
        break;
      case GeometryType::kSphere:
        item.fcl = std::make_shared<fcl::Sphered>(g.radius);
        item.extent = g.radius;
        break;
      case GeometryType::kCapsule:
        item.fcl = std::make_shared<fcl::Capsuled>(g.radius, g.length);
        item.extent = 0.5 * g.length + g.radius;
        break;
      case GeometryType::kCylinder:
        item.fcl = std::make_shared<fcl::Cylinderd>(g.radius, g.length);
        item.extent = std::hypot(0.5 * g.length, g.radius);
        break;
      case GeometryType::kMesh:
        item.fcl = ReadStl(g.mesh_path, g.scale, owner, &item.extent);
        break;
    }
  }
};

CollisionWorld::CollisionWorld(const Model& model) : impl_(std::make_unique<Impl>()) {
  for (int b = 0; b < model.num_bodies(); ++b) {
    impl_->parents.push_back(model.parent(b));
    impl_->body_names.push_back(model.body(b).name);
    for (const Geometry& g : model.body(b).collisions) {
      Impl::Item item;
      item.name = g.name;
      item.body = b;
      item.geometry = g;
      item.X_WG = g.X_BG;
      impl_->Prepare(item, "body '" + model.body(b).name + "', collision '" + g.name + "'");
      // Geometry names from URDF files may repeat across links; qualify duplicates with the body name.
      for (const Impl::Item& other : impl_->items) {
        if (other.name == item.name) item.name = model.body(b).name + "/" + g.name;
      }
      impl_->Add(std::move(item));
    }
  }
}

CollisionWorld::~CollisionWorld() = default;
CollisionWorld::CollisionWorld(CollisionWorld&&) noexcept = default;
CollisionWorld& CollisionWorld::operator=(CollisionWorld&&) noexcept = default;

int CollisionWorld::AddBox(const std::string& name, const Eigen::Vector3d& size, const Pose& X_WG) {
  if (!(size.minCoeff() > 0.0) || !size.allFinite()) {
    throw std::invalid_argument("CollisionWorld::AddBox('" + name + "'): side lengths must be positive and finite");
  }
  Impl::Item item;
  item.name = name;
  item.geometry.name = name;
  item.geometry.type = GeometryType::kBox;
  item.geometry.size = size;
  item.X_WG = X_WG;
  impl_->Prepare(item, name);
  return impl_->Add(std::move(item));
}

int CollisionWorld::AddSphere(const std::string& name, double radius, const Eigen::Vector3d& center) {
  if (!(radius > 0.0) || !std::isfinite(radius)) {
    throw std::invalid_argument("CollisionWorld::AddSphere('" + name + "'): radius " + FormatShort(radius) +
                                " must be positive and finite");
  }
  Impl::Item item;
  item.name = name;
  item.geometry.name = name;
  item.geometry.type = GeometryType::kSphere;
  item.geometry.radius = radius;
  item.X_WG = Pose(Eigen::Matrix3d::Identity(), center);
  impl_->Prepare(item, name);
  return impl_->Add(std::move(item));
}

int CollisionWorld::AddPoints(const std::string& name, const Eigen::Matrix3Xd& points, double radius) {
  if (points.cols() == 0 || !points.allFinite()) {
    throw std::invalid_argument("CollisionWorld::AddPoints('" + name + "'): give at least one finite point");
  }
  if (!(radius >= 0.0) || !std::isfinite(radius)) {
    throw std::invalid_argument("CollisionWorld::AddPoints('" + name + "'): radius " + FormatShort(radius) +
                                " must be >= 0");
  }
  Impl::Item item;
  item.name = name;
  item.is_points = true;
  item.points = points;
  item.point_radius = radius;
  return impl_->Add(std::move(item));
}

int CollisionWorld::AddHeightField(const std::string& name, const Eigen::MatrixXd& heights, double cell_size,
                                   const Eigen::Vector2d& origin, double bottom) {
  if (heights.size() == 0) {
    throw std::invalid_argument("CollisionWorld::AddHeightField('" + name + "'): the height grid is empty");
  }
  if (!(cell_size > 0.0) || !std::isfinite(cell_size)) {
    throw std::invalid_argument("CollisionWorld::AddHeightField('" + name + "'): cell size " +
                                FormatShort(cell_size) + " must be positive");
  }
  if (!origin.allFinite() || !std::isfinite(bottom)) {
    throw std::invalid_argument("CollisionWorld::AddHeightField('" + name + "'): origin and bottom must be finite");
  }
  for (Eigen::Index k = 0; k < heights.size(); ++k) {
    const double h = heights.data()[k];
    if (std::isinf(h) || (!std::isnan(h) && h < bottom)) {
      throw std::invalid_argument("CollisionWorld::AddHeightField('" + name + "'): height " + FormatShort(h) +
                                  " is infinite or below the bottom " + FormatShort(bottom) +
                                  "; lower the bottom or mark unknown cells with NaN");
    }
  }
  Impl::Item item;
  item.name = name;
  item.is_height_field = true;
  item.heights = heights;
  item.cell_size = cell_size;
  item.origin = origin;
  item.bottom = bottom;
  return impl_->Add(std::move(item));
}

void CollisionWorld::ExcludeBodyPair(const std::string& body_a, const std::string& body_b) {
  auto find = [&](const std::string& name) {
    const auto& names = impl_->body_names;
    const auto it = std::find(names.begin(), names.end(), name);
    if (it == names.end()) {
      throw std::invalid_argument("CollisionWorld::ExcludeBodyPair: unknown body '" + name + "'; did you mean " +
                                  QuotedList(ClosestNames(name, names)) + "?");
    }
    return static_cast<int>(it - names.begin());
  };
  impl_->excluded_bodies.insert(std::minmax(find(body_a), find(body_b)));
  impl_->RebuildFilter();
}

void CollisionWorld::ExcludeGeometryPair(const std::string& geometry_a, const std::string& geometry_b) {
  impl_->excluded_geometries.insert(std::minmax(GetGeometryIndex(geometry_a), GetGeometryIndex(geometry_b)));
  impl_->RebuildFilter();
}

void CollisionWorld::UpdatePoses(const Model& model, const Data& data) {
  if (static_cast<int>(impl_->parents.size()) != model.num_bodies() ||
      static_cast<int>(data.X_world.size()) != model.num_bodies()) {
    throw std::invalid_argument(
        "CollisionWorld::UpdatePoses: the model or data is not the one the world was built "
        "from (" +
        std::to_string(impl_->parents.size()) + " bodies)");
  }
  for (Impl::Item& item : impl_->items) {
    if (item.body < 0) continue;
    item.X_WG = data.X_world[static_cast<std::size_t>(item.body)] * item.geometry.X_BG;
    impl_->UpdateBox(item);
  }
}

int CollisionWorld::num_geometries() const { return static_cast<int>(impl_->items.size()); }
const std::string& CollisionWorld::geometry_name(int i) const {
  return impl_->items.at(static_cast<std::size_t>(i)).name;
}
int CollisionWorld::geometry_body(int i) const { return impl_->items.at(static_cast<std::size_t>(i)).body; }
const Pose& CollisionWorld::geometry_pose(int i) const { return impl_->items.at(static_cast<std::size_t>(i)).X_WG; }

int CollisionWorld::GetGeometryIndex(const std::string& name) const {
  std::vector<std::string> names;
  for (std::size_t i = 0; i < impl_->items.size(); ++i) {
    if (impl_->items[i].name == name) return static_cast<int>(i);
    names.push_back(impl_->items[i].name);
  }
  throw std::invalid_argument("CollisionWorld: unknown geometry '" + name + "'; did you mean " +
                              QuotedList(ClosestNames(name, names)) + "?");
}

bool CollisionWorld::IsPairChecked(int a, int b) const {
  const int n = num_geometries();
  if (a < 0 || a >= n || b < 0 || b >= n) {
    throw std::invalid_argument("CollisionWorld::IsPairChecked: geometry indices " + std::to_string(a) + ", " +
                                std::to_string(b) + " must lie in [0, " + std::to_string(n) + ")");
  }
  return impl_->Checked(a, b);
}

ShapeDistance CollisionWorld::ComputeDistance(int a, int b) const {
  const int n = num_geometries();
  if (a < 0 || a >= n || b < 0 || b >= n) {
    throw std::invalid_argument("CollisionWorld::ComputeDistance: geometry indices " + std::to_string(a) + ", " +
                                std::to_string(b) + " must lie in [0, " + std::to_string(n) + ")");
  }
  return impl_->Distance(a, b);
}

std::vector<CollisionPair> CollisionWorld::PairsWithin(double margin) const {
  if (std::isnan(margin)) {
    throw std::invalid_argument("CollisionWorld::PairsWithin: the margin is NaN; give a distance in metres "
                                "(infinity for every pair)");
  }
  std::vector<CollisionPair> pairs;
  const int n = num_geometries();
  for (int a = 0; a < n; ++a) {
    const Impl::Item& A = impl_->items[static_cast<std::size_t>(a)];
    for (int b = a + 1; b < n; ++b) {
      const Impl::Item& B = impl_->items[static_cast<std::size_t>(b)];
      // Broadphase: world boxes inflated by the margin must overlap.
      if (((A.box_min.array() - margin) > B.box_max.array()).any() ||
          ((B.box_min.array() - margin) > A.box_max.array()).any()) {
        continue;
      }
      if (!impl_->Checked(a, b)) continue;
      // Keep the robot geometry first when the other one is environment.
      const bool swap = A.body < 0;
      CollisionPair pair;
      pair.geometry_a = swap ? b : a;
      pair.geometry_b = swap ? a : b;
      pair.result = impl_->Distance(pair.geometry_a, pair.geometry_b, margin);
      if (pair.result.distance < margin) pairs.push_back(pair);
    }
  }
  return pairs;
}

CollisionPair CollisionWorld::ClosestPair(double max_distance) const {
  if (std::isnan(max_distance)) {
    throw std::invalid_argument("CollisionWorld::ClosestPair: max_distance is NaN; give a distance in metres "
                                "(infinity for no limit)");
  }
  CollisionPair best;
  best.result.distance = max_distance;
  for (const CollisionPair& pair : PairsWithin(max_distance)) {
    if (pair.result.distance < best.result.distance) best = pair;
  }
  if (best.geometry_a < 0) best.result.distance = std::numeric_limits<double>::infinity();
  return best;
}

void CollisionWorld::DistanceGradient(const Model& model, const Data& data, const CollisionPair& pair,
                                      Eigen::Ref<Eigen::VectorXd> gradient) const {
  if (gradient.size() != model.nv()) {
    throw std::invalid_argument("CollisionWorld::DistanceGradient: gradient has size " +
                                std::to_string(gradient.size()) + ", expected nv = " + std::to_string(model.nv()));
  }
  gradient.setZero();
  const Eigen::Vector3d& n = pair.result.normal;
  auto accumulate = [&](int geometry, const Eigen::Vector3d& p, double sign) {
    for (int i = geometry_body(geometry); i > 0; i = model.parent(i)) {
      const Joint& joint = model.joint(i);
      const Pose& X = data.X_world[static_cast<std::size_t>(i)];
      for (int k = 0; k < joint.nv; ++k) {
        const Vector6d s = X.ActMotion(internal::MotionSubspaceColumn(joint, k));
        gradient[joint.idx_v + k] += sign * n.dot(s.tail<3>() + s.head<3>().cross(p));
      }
    }
  };
  accumulate(pair.geometry_b, pair.result.p_B, 1.0);
  accumulate(pair.geometry_a, pair.result.p_A, -1.0);
}

}  // namespace cairn::multibody
