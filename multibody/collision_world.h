#pragma once

#include <cstddef>
#include <limits>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include <cairn/multibody/data.h>
#include <cairn/multibody/geometry.h>
#include <cairn/multibody/model.h>
#include <cairn/multibody/shape_distance.h>

namespace cairn::multibody {

/// Largest mesh file CollisionWorld reads: 256 MiB (about 5 million binary STL triangles). Collision meshes are
/// usually simplified to a few thousand triangles; the bound keeps a wrong path (a device, a huge scan) from
/// being read into memory whole.
inline constexpr std::size_t kMaxMeshBytes = std::size_t{256} << 20;

/// A pair of collision geometries (indices into the world) and their signed distance.
struct CollisionPair {
  /// First geometry (always a robot geometry when one of the two is environment).
  int geometry_a = -1;
  /// Second geometry.
  int geometry_b = -1;
  /// Signed distance, witness points and normal from a to b, in the world frame.
  ShapeDistance result;
};

/// The robot's collision shapes, placed by forward kinematics, together with environment geometry (boxes,
/// spheres, point sets, height fields), answering signed-distance queries for collision avoidance.
///
/// Sphere, capsule and box pairs, and points and height-field cells against them, use the closed forms of
/// shape_distance.h. Pairs with a cylinder or a mesh go through FCL 0.7: libccd signed distance for the convex
/// primitives; for meshes FCL gives unsigned distances, so overlapping mesh pairs report distance 0. Mesh files
/// are read as STL (binary or ASCII); other formats are rejected when the world is built. A broadphase of world
/// axis-aligned boxes prunes pairs before any narrowphase. Pairs are filtered: geometries of the same body, of a
/// body and its parent (adjacent links), explicitly excluded body or geometry pairs, and environment against
/// environment are never reported. Results are ordered by (geometry_a, geometry_b), so they are deterministic.
class CollisionWorld {
 public:
  /// Takes the collision geometry of every body of `model` (geometry i keeps the body's order of shapes).
  /// Throws std::invalid_argument for a mesh file that is not a readable STL, is larger than kMaxMeshBytes or
  /// holds a vertex that is not finite.
  explicit CollisionWorld(const Model& model);
  ~CollisionWorld();
  CollisionWorld(CollisionWorld&&) noexcept;
  CollisionWorld& operator=(CollisionWorld&&) noexcept;

  /// Adds a fixed environment box (full side lengths) at pose X_WG; returns its geometry index.
  int AddBox(const std::string& name, const Eigen::Vector3d& size, const Pose& X_WG);
  /// Adds a fixed environment sphere.
  int AddSphere(const std::string& name, double radius, const Eigen::Vector3d& center);
  /// Adds a point set (e.g. a stereo point cloud), each point inflated by `radius` >= 0.
  int AddPoints(const std::string& name, const Eigen::Matrix3Xd& points, double radius = 0.0);

  /// Adds an elevation map: cell (i, j) covers x in origin.x + [i, i + 1) * cell_size and y in
  /// origin.y + [j, j + 1) * cell_size, and is solid from `bottom` up to heights(i, j) (a vertical box, so the
  /// closed forms apply); NaN marks an unknown cell, which is left out. Throws std::invalid_argument for an empty
  /// grid, a non-positive cell size or a height below `bottom`.
  int AddHeightField(const std::string& name, const Eigen::MatrixXd& heights, double cell_size,
                     const Eigen::Vector2d& origin, double bottom);

  /// Never report pairs between the geometries of bodies `body_a` and `body_b` (names; unknown names throw
  /// listing the closest ones).
  void ExcludeBodyPair(const std::string& body_a, const std::string& body_b);
  /// Never report the pair of geometries called `geometry_a` and `geometry_b`.
  void ExcludeGeometryPair(const std::string& geometry_a, const std::string& geometry_b);

  /// Places the robot geometries from the body poses in `data` (run ForwardKinematics first).
  void UpdatePoses(const Model& model, const Data& data);

  /// Number of geometries (robot first, then environment in the order added).
  int num_geometries() const;
  /// Name of geometry `i`.
  const std::string& geometry_name(int i) const;
  /// Body carrying geometry `i`, or -1 for environment geometry.
  int geometry_body(int i) const;
  /// Index of the geometry called `name`; throws std::invalid_argument listing the closest names if unknown.
  int GetGeometryIndex(const std::string& name) const;
  /// Pose of geometry `i` in the world (as of the last UpdatePoses).
  const Pose& geometry_pose(int i) const;
  /// True if the pair (a, b) passes the filters.
  bool IsPairChecked(int a, int b) const;

  /// Signed distance between geometries a and b (no filtering).
  ShapeDistance ComputeDistance(int a, int b) const;

  /// Every checked pair whose signed distance is below `margin`, ordered by (geometry_a, geometry_b); throws
  /// std::invalid_argument for a NaN margin.
  std::vector<CollisionPair> PairsWithin(double margin) const;

  /// The checked pair with the smallest signed distance among those closer than `max_distance`; geometry_a is
  /// -1 if there is none. Throws std::invalid_argument for a NaN max_distance.
  CollisionPair ClosestPair(double max_distance = std::numeric_limits<double>::infinity()) const;

  /// Gradient of pair.result.distance with respect to a tangent perturbation of q (size nv), from the witness
  /// points held fixed to their bodies and the joint motions in `data` (the poses the pair was computed at):
  /// d(distance)/dq = normal . (J_B(p_B) - J_A(p_A)).
  void DistanceGradient(const Model& model, const Data& data, const CollisionPair& pair,
                        Eigen::Ref<Eigen::VectorXd> gradient) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace cairn::multibody
