#pragma once

/// @file
/// Centre of mass, its Jacobian, and the per-subtree mass tables they share with the gravity torques.

#include <Eigen/Core>

#include <cairn/multibody/data.h>
#include <cairn/multibody/model.h>

namespace cairn::multibody {

/// Runs ForwardKinematics(q) and returns the centre of mass in the world (also data.com). Fills
/// data.subtree_mass and data.subtree_first_moment. Throws std::invalid_argument on a wrong q size; throws
/// std::runtime_error for a massless model (no centre of mass exists).
const Eigen::Vector3d& CenterOfMass(const Model& model, Data& data, const Eigen::Ref<const Eigen::VectorXd>& q);

/// Runs CenterOfMass(q) and returns the 3 x nv Jacobian of the centre of mass (also data.com_jacobian); fills
/// data.joint_motion_world.
const Eigen::Matrix<double, 3, Eigen::Dynamic>& CenterOfMassJacobian(const Model& model, Data& data,
                                                                     const Eigen::Ref<const Eigen::VectorXd>& q);

namespace internal {
/// From the poses in `data`, fills the subtree masses and first moments and the world motion subspace.
void ComputeSubtreeMassesAndMotion(const Model& model, Data& data);
}  // namespace internal

}  // namespace cairn::multibody
