#pragma once

/// @file
/// Static gravity torques (thesis eq. 2.11) and their derivative, for the whole-body planner's cost.

#include <Eigen/Core>

#include <cairn/multibody/data.h>
#include <cairn/multibody/model.h>

namespace cairn::multibody {

/// Generalized forces that hold the robot still against gravity at q: tau = sum_i J_i(q)^T m_i (-g), i.e.
/// InverseDynamics(q, 0, 0), computed in O(n) from subtree centres of mass. Result in data.gravity_torques.
const Eigen::VectorXd& GravityTorques(const Model& model, Data& data, const Eigen::Ref<const Eigen::VectorXd>& q);

/// d(GravityTorques)/dq as an nv x nv matrix: column k is the derivative along the tangent direction e_k, i.e.
/// d/de [GravityTorques(Integrate(q, e * e_k, 1))] at e = 0 (for revolute and prismatic joints this is the
/// plain partial derivative). Also fills data.gravity_torques. Result in data.gravity_torques_derivative.
const Eigen::MatrixXd& GravityTorquesDerivative(const Model& model, Data& data,
                                                const Eigen::Ref<const Eigen::VectorXd>& q);

}  // namespace cairn::multibody
