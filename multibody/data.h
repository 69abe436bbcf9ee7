#pragma once

#include <vector>

#include <Eigen/Core>

#include <cairn/multibody/model.h>
#include <cairn/multibody/pose.h>
#include <cairn/multibody/spatial_inertia.h>

namespace cairn::multibody {

/// Most velocity coordinates a Data serves: 10,000. Data holds three dense nv x nv matrices (the mass matrix,
/// its factor and the gravity-torque derivative), 2.4 GB at this limit, so a larger model is refused before
/// anything is allocated rather than exhausting memory.
inline constexpr int kMaxDataVelocities = 10000;

/// The workspace of the multibody algorithms for one Model: every buffer is sized once here, so the
/// algorithms never allocate. Use one Data per thread. It is a plain struct because the free-function
/// algorithms fill it and callers read the results they asked for (Pinocchio's layout); each field says
/// which algorithm writes it. Per-body vectors are indexed by body index (entry 0 is the world).
struct Data {
  /// Sizes every buffer for `model`; throws std::invalid_argument if the model has more than kMaxDataVelocities
  /// velocity coordinates.
  explicit Data(const Model& model);

  /// nq of the model this workspace was made for (the algorithms check it).
  int nq;
  /// nv of the model this workspace was made for.
  int nv;

  /// X_parent[i]: pose of body i in its parent (ForwardKinematics).
  std::vector<Pose> X_parent;
  /// X_world[i]: pose of body i in the world (ForwardKinematics).
  std::vector<Pose> X_world;
  /// v[i]: twist of body i in its own frame (ForwardKinematics with velocities, InverseDynamics).
  std::vector<Vector6d> v;
  /// a[i]: spatial acceleration of body i in its frame; ForwardKinematics stores the true acceleration,
  /// InverseDynamics the acceleration with gravity folded in (a - g).
  std::vector<Vector6d> a;
  /// f[i]: force transmitted by joint i onto body i, in body i's frame (InverseDynamics).
  std::vector<Vector6d> f;
  /// Composite (subtree) inertias, expressed in the world frame (MassMatrix).
  std::vector<SpatialInertia> composite_inertia;
  /// Mass of the subtree rooted at each body (CenterOfMass, GravityTorques).
  std::vector<double> subtree_mass;
  /// First moment (mass times centre of mass, world frame) of each subtree (CenterOfMass, GravityTorques).
  std::vector<Eigen::Vector3d> subtree_first_moment;
  /// World-frame motion subspace of every velocity coordinate, as spatial vectors about the world origin
  /// (6 x nv; written by GravityTorques, CenterOfMassJacobian, MassMatrix).
  Eigen::Matrix<double, 6, Eigen::Dynamic> joint_motion_world;

  /// Joint torques (InverseDynamics).
  Eigen::VectorXd tau;
  /// Gravity torques (GravityTorques).
  Eigen::VectorXd gravity_torques;
  /// Derivative of the gravity torques with respect to a tangent perturbation of q (GravityTorquesDerivative).
  Eigen::MatrixXd gravity_torques_derivative;
  /// Mass matrix (MassMatrix; both triangles filled).
  Eigen::MatrixXd M;
  /// Coriolis, centrifugal and gravity terms C(q, v) v + g(q) (ForwardDynamics).
  Eigen::VectorXd nonlinear_effects;
  /// Accelerations (ForwardDynamics).
  Eigen::VectorXd qdd;
  /// Sparse L^T D L factor of M along the kinematic tree (ForwardDynamics): D on the diagonal, L below it.
  Eigen::MatrixXd mass_factor;
  /// Scratch list of body indices (FrameJacobian's path to the root).
  std::vector<int> body_path;
  /// Centre of mass in the world (CenterOfMass).
  Eigen::Vector3d com;
  /// Jacobian of the centre of mass, 3 x nv (CenterOfMassJacobian).
  Eigen::Matrix<double, 3, Eigen::Dynamic> com_jacobian;
};

}  // namespace cairn::multibody
