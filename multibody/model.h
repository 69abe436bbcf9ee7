#pragma once

#include <map>
#include <string>
#include <vector>

#include <Eigen/Core>

#include <cairn/multibody/body.h>
#include <cairn/multibody/frame.h>
#include <cairn/multibody/joint.h>

namespace cairn::multibody {

class ModelBuilder;

/// An immutable kinematic tree of rigid bodies, built by ModelBuilder or the URDF parser.
///
/// Body 0 is the world. Every other body i has exactly one parent joint, joint i, connecting body parent(i) < i
/// to body i, so the bodies are in topological order and the algorithms run as single forward/backward sweeps.
/// joint(0) is the fixed world joint named "universe" (as in Pinocchio), with no degrees of freedom.
/// Configurations q (size nq) and velocities v (size nv) stack the joints' coordinates in body order.
/// Thread-safe to share; each thread uses its own Data.
class Model {
 public:
  /// Model name (the URDF robot name).
  const std::string& name() const { return name_; }
  /// Size of a configuration vector.
  int nq() const { return nq_; }
  /// Size of a velocity vector.
  int nv() const { return nv_; }
  /// Number of bodies including the world.
  int num_bodies() const { return static_cast<int>(bodies_.size()); }
  /// Number of named frames (one per body, then the extra frames).
  int num_frames() const { return static_cast<int>(frames_.size()); }
  /// Body `i` (0 is the world).
  const Body& body(int i) const { return bodies_.at(static_cast<std::size_t>(i)); }
  /// Joint `i`, the parent joint of body `i` (0 is the fixed "universe" joint of the world).
  const Joint& joint(int i) const { return joints_.at(static_cast<std::size_t>(i)); }
  /// Frame `i`.
  const Frame& frame(int i) const { return frames_.at(static_cast<std::size_t>(i)); }
  /// All bodies, world first.
  const std::vector<Body>& bodies() const { return bodies_; }
  /// All joints, index-aligned with bodies.
  const std::vector<Joint>& joints() const { return joints_; }
  /// All frames.
  const std::vector<Frame>& frames() const { return frames_; }
  /// Parent body of body `i` (-1 for the world).
  int parent(int i) const { return joints_[static_cast<std::size_t>(i)].parent; }
  /// Joint owning velocity coordinate `iv`.
  int velocity_joint(int iv) const { return velocity_joint_.at(static_cast<std::size_t>(iv)); }
  /// The velocity coordinate that precedes `iv` on the path to the root (the previous coordinate of the same
  /// joint, else the last coordinate of the nearest moving ancestor joint), -1 at the root. Always < iv; the
  /// mass matrix is zero outside the entries linking a coordinate to this chain, which sparse factorizations use.
  int velocity_parent(int iv) const { return velocity_parent_[static_cast<std::size_t>(iv)]; }
  /// True if body `ancestor` is body `body` or one of its ancestors.
  bool IsAncestorOrSelf(int ancestor, int body) const;

  /// Index of the body called `name`; throws std::invalid_argument listing the closest names if unknown.
  int GetBodyIndex(const std::string& name) const;
  /// Index of the joint called `name` (>= 1); throws std::invalid_argument listing the closest names if unknown.
  int GetJointIndex(const std::string& name) const;
  /// Index of the frame called `name`; throws std::invalid_argument listing the closest names if unknown.
  int GetFrameIndex(const std::string& name) const;
  /// True if a body called `name` exists.
  bool HasBody(const std::string& name) const;
  /// True if a joint called `name` exists.
  bool HasJoint(const std::string& name) const;
  /// True if a frame called `name` exists.
  bool HasFrame(const std::string& name) const;

  /// Sum of the bodies' masses.
  double total_mass() const { return total_mass_; }
  /// Gravity acceleration in the world frame (default [0, 0, -9.81]).
  const Eigen::Vector3d& gravity() const { return gravity_; }
  /// A copy of this model with another gravity vector (the model itself stays immutable).
  Model WithGravity(const Eigen::Vector3d& gravity) const;

  /// Lower position limits per configuration coordinate (-inf where unlimited; -1 for quaternion parts).
  const Eigen::VectorXd& lower_position_limits() const { return lower_position_limits_; }
  /// Upper position limits per configuration coordinate (+inf where unlimited; +1 for quaternion parts).
  const Eigen::VectorXd& upper_position_limits() const { return upper_position_limits_; }
  /// Velocity limits per velocity coordinate (+inf where unlimited).
  const Eigen::VectorXd& velocity_limits() const { return velocity_limits_; }
  /// Effort limits per velocity coordinate (+inf where unlimited).
  const Eigen::VectorXd& effort_limits() const { return effort_limits_; }

  /// Names of all bodies, in index order.
  std::vector<std::string> body_names() const;
  /// Names of all joints except the fixed "universe" world joint, in index order.
  std::vector<std::string> joint_names() const;
  /// Names of all frames, in index order.
  std::vector<std::string> frame_names() const;

 private:
  friend class ModelBuilder;
  Model() = default;

  std::string name_;
  int nq_ = 0;
  int nv_ = 0;
  std::vector<Body> bodies_;
  std::vector<Joint> joints_;
  std::vector<Frame> frames_;
  std::vector<int> velocity_joint_;
  std::vector<int> velocity_parent_;
  std::map<std::string, int> body_index_;
  std::map<std::string, int> joint_index_;
  std::map<std::string, int> frame_index_;
  double total_mass_ = 0.0;
  Eigen::Vector3d gravity_ = Eigen::Vector3d(0.0, 0.0, -9.81);
  Eigen::VectorXd lower_position_limits_;
  Eigen::VectorXd upper_position_limits_;
  Eigen::VectorXd velocity_limits_;
  Eigen::VectorXd effort_limits_;
};

}  // namespace cairn::multibody
