#pragma once

/// @file
/// Objects of the haptic-affordance simulation (seed 000): geometry for the depth sensor with, per element, the
/// ground-truth stiffness the antenna feels.

#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

namespace cairn::perception {

/// One element of an object, in the world frame W (z up, ground at z = 0).
struct HapticPrimitive {
  enum class Shape {
    /// Centre `a`, radius `radius`.
    kSphere,
    /// Segment a–b swept by a ball of `radius` (stems, branches, logs).
    kCapsule,
    /// Axis-aligned box: centre `a`, half extents `b`.
    kBox,
  };
  Shape shape{Shape::kSphere};
  Eigen::Vector3d a{Eigen::Vector3d::Zero()};
  Eigen::Vector3d b{Eigen::Vector3d::Zero()};
  double radius{0.0};
  /// A stiff element blocks the antenna (a trunk, a rock, a log); a soft one bends out of its way (leaves, thin
  /// stems and branches).
  bool stiff{false};
};

/// An object: named primitives and its traversability (an object is traversable when none of its elements is
/// stiff, the paper's "the inability of the antenna to bend or trespass the object" read the other way round).
class HapticSceneObject {
 public:
  /// Most primitives an object may have.
  static constexpr int kMaxPrimitives = 100000;

  /// Throws std::invalid_argument for a non-finite or non-positive size (naming the primitive) or more than
  /// kMaxPrimitives primitives.
  HapticSceneObject(std::string name, std::vector<HapticPrimitive> primitives);

  const std::string& name() const { return name_; }
  const std::vector<HapticPrimitive>& primitives() const { return primitives_; }
  /// True when no primitive is stiff.
  bool traversable() const { return traversable_; }
  /// A sphere enclosing every primitive, to skip rays that miss the object.
  const Eigen::Vector3d& bounding_center() const { return bounding_center_; }
  double bounding_radius() const { return bounding_radius_; }

  /// The same object moved by `offset`.
  HapticSceneObject Translated(const Eigen::Vector3d& offset) const;

  /// The nearest hit of the ray origin + t dir (dir unit) with t in (0, max_t], if any.
  std::optional<double> CastRay(const Eigen::Vector3d& origin, const Eigen::Vector3d& dir, double max_t) const;

  /// The signed distance from p to the nearest stiff element (+infinity when none).
  double StiffDistance(const Eigen::Vector3d& p) const;

 private:
  std::string name_;
  std::vector<HapticPrimitive> primitives_;
  bool traversable_{true};
  Eigen::Vector3d bounding_center_{Eigen::Vector3d::Zero()};
  double bounding_radius_{0.0};
};

}  // namespace cairn::perception
