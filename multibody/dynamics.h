#pragma once

/// @file
/// Rigid-body dynamics M(q) qdd + C(q, v) v + g(q) = tau: inverse dynamics (RNEA), the mass matrix (CRBA),
/// forward dynamics (CRBA + Cholesky), energies and centroidal momentum.

#include <Eigen/Core>

#include <cairn/multibody/data.h>
#include <cairn/multibody/model.h>

namespace cairn::multibody {

/// Recursive Newton-Euler: the generalized forces tau that produce accelerations a at (q, v) under the model's
/// gravity. Result in data.tau (also fills data.v, data.a, data.f). No allocation.
const Eigen::VectorXd& InverseDynamics(const Model& model, Data& data, const Eigen::Ref<const Eigen::VectorXd>& q,
                                       const Eigen::Ref<const Eigen::VectorXd>& v,
                                       const Eigen::Ref<const Eigen::VectorXd>& a);

/// Composite rigid body algorithm: the joint-space mass matrix M(q) (both triangles). Result in data.M.
const Eigen::MatrixXd& MassMatrix(const Model& model, Data& data, const Eigen::Ref<const Eigen::VectorXd>& q);

/// Accelerations qdd = M(q)^-1 (tau - C(q, v) v - g(q)). Result in data.qdd. Throws std::runtime_error if
/// M(q) is not positive definite (a moving joint that carries no mass).
const Eigen::VectorXd& ForwardDynamics(const Model& model, Data& data, const Eigen::Ref<const Eigen::VectorXd>& q,
                                       const Eigen::Ref<const Eigen::VectorXd>& v,
                                       const Eigen::Ref<const Eigen::VectorXd>& tau);

/// Kinetic energy 1/2 v^T M(q) v (computed from body twists, without forming M).
double KineticEnergy(const Model& model, Data& data, const Eigen::Ref<const Eigen::VectorXd>& q,
                     const Eigen::Ref<const Eigen::VectorXd>& v);

/// Potential energy of gravity, -sum_i m_i g . c_i (zero at the world origin).
double PotentialEnergy(const Model& model, Data& data, const Eigen::Ref<const Eigen::VectorXd>& q);

/// Centroidal momentum [k_G; l]: angular momentum about the centre of mass and linear momentum, in world axes.
/// Throws std::runtime_error for a massless model.
Vector6d CentroidalMomentum(const Model& model, Data& data, const Eigen::Ref<const Eigen::VectorXd>& q,
                            const Eigen::Ref<const Eigen::VectorXd>& v);

}  // namespace cairn::multibody
