#pragma once

/// @file
/// Operations on configurations: the neutral configuration, Integrate/Difference on the configuration
/// manifold (a floating joint's pose moves by the SE(3) exponential of its body twist), random samples and
/// joint-limit helpers.

#include <random>

#include <Eigen/Core>

#include <cairn/multibody/model.h>

namespace cairn::multibody {

/// All joint coordinates zero, floating joints at the identity pose (quaternion w = 1).
Eigen::VectorXd NeutralConfiguration(const Model& model);

/// q (+) v dt: revolute/prismatic coordinates add v dt; a floating joint's pose becomes X * exp(v dt) with v its
/// body twist [ω; v]. Throws std::invalid_argument on wrong sizes.
Eigen::VectorXd Integrate(const Model& model, const Eigen::Ref<const Eigen::VectorXd>& q,
                          const Eigen::Ref<const Eigen::VectorXd>& v, double dt = 1.0);

/// The velocity v (size nv) with Integrate(q0, v, 1) = q1 (the SE(3) logarithm for floating joints).
Eigen::VectorXd Difference(const Model& model, const Eigen::Ref<const Eigen::VectorXd>& q0,
                           const Eigen::Ref<const Eigen::VectorXd>& q1);

/// Time derivative of q (size nq) when the robot moves with velocity v: for a floating joint, the position
/// rate R v_linear and the quaternion rate 1/2 quat (x) (0, ω). For integrating with ordinary ODE schemes.
Eigen::VectorXd ConfigurationRate(const Model& model, const Eigen::Ref<const Eigen::VectorXd>& q,
                                  const Eigen::Ref<const Eigen::VectorXd>& v);

/// Rescales every floating joint's quaternion to unit length (throws std::invalid_argument for a zero one).
void NormalizeConfiguration(const Model& model, Eigen::Ref<Eigen::VectorXd> q);

/// A random configuration: limited coordinates uniform within their limits, unlimited ones uniform in
/// [-unlimited_range, unlimited_range], floating joints at a uniform random orientation and a position with
/// coordinates uniform in [-unlimited_range, unlimited_range]. Deterministic for a given generator state.
/// Throws std::invalid_argument unless unlimited_range is finite and >= 0.
Eigen::VectorXd RandomConfiguration(const Model& model, std::mt19937& rng, double unlimited_range = 3.141592653589793);

/// True if every limited coordinate of q lies within its limits enlarged by `tolerance` (>= 0; NaN throws).
bool IsWithinPositionLimits(const Model& model, const Eigen::Ref<const Eigen::VectorXd>& q, double tolerance = 0.0);

/// Per coordinate, how far q lies outside its position limits (0 inside; positive above the upper limit,
/// negative below the lower limit). Quaternion coordinates always report 0.
Eigen::VectorXd PositionLimitViolation(const Model& model, const Eigen::Ref<const Eigen::VectorXd>& q);

/// q with every limited coordinate clamped into its limits (an explicit request, never done silently).
Eigen::VectorXd ClampToPositionLimits(const Model& model, const Eigen::Ref<const Eigen::VectorXd>& q);

}  // namespace cairn::multibody
