#pragma once

#include <set>
#include <string>
#include <vector>

#include <Eigen/Core>

#include <cairn/multibody/model.h>

namespace cairn::multibody {

/// Most bodies a model may have besides the world: 100,000. Real robots have a few hundred at most; the bound
/// keeps a generated or corrupt file from building a model that no Data (kMaxDataVelocities) could serve.
inline constexpr int kMaxModelBodies = 100000;

/// Relative slack of the triangle-inequality check on principal moments of inertia: a body is refused when
/// I1 + I2 < I3 - kInertiaTriangleTolerance * I3 (I1 <= I2 <= I3), which allows moments rounded in a file.
inline constexpr double kInertiaTriangleTolerance = 1e-3;

/// Assembles a Model body by body, checking each piece as it is added, then freezes it with Build().
///
/// Bodies must be added after their parent, so indices come out in topological order; Build() reorders nothing
/// but computes the coordinate layout and derived tables. The builder is how the URDF parser and tests make
/// models; a built Model is never modified.
class ModelBuilder {
 public:
  /// Starts a model called `model_name` holding only the world body (index 0, named "world").
  explicit ModelBuilder(std::string model_name = "model");

  /// Adds `body` attached to body `parent` through `joint` (its `parent`, `idx_q`, `idx_v`, `nq`, `nv` fields
  /// are filled in here). Returns the new body's index. Throws std::invalid_argument on a duplicate body or
  /// joint name, an unknown parent, a zero axis, a negative or non-finite mass, an inertia that is not
  /// positive definite (positive semi-definite for a massless body) or whose principal moments violate the
  /// triangle inequality, NaN or crossed limits, negative velocity or effort limits, or a model that already
  /// has kMaxModelBodies bodies.
  int AddBody(int parent, Body body, Joint joint);

  /// Adds a collision shape to body `body` (checks the shape's dimensions).
  void AddCollisionGeometry(int body, const Geometry& geometry);
  /// Adds a visual shape to body `body`.
  void AddVisualGeometry(int body, const Geometry& geometry);
  /// Adds an extra named frame on body `body` (the built model lists it after the bodies' own frames).
  void AddFrame(const std::string& name, int body, const Pose& X_BF);
  /// Sets the gravity vector (default [0, 0, -9.81]).
  void SetGravity(const Eigen::Vector3d& gravity);

  /// Number of bodies added so far, including the world.
  int num_bodies() const { return static_cast<int>(model_.bodies_.size()); }
  /// Index of an already added body; throws std::invalid_argument listing the closest names if unknown.
  int GetBodyIndex(const std::string& name) const;

  /// Returns the finished model. The builder is left empty.
  Model Build();

 private:
  void CheckBodyIndex(int body, const char* what) const;

  Model model_;
  std::vector<Frame> extra_frames_;
  // Names taken so far, so that adding a body costs O(log n) rather than a scan of all bodies.
  std::set<std::string> body_names_;
  std::set<std::string> joint_names_;
};

}  // namespace cairn::multibody
