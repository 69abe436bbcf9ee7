#pragma once

#include <vector>

#include <Eigen/Core>

#include <cairn/multibody/model.h>

namespace cairn::planning {

/// The ZMP of a sampled motion from the full rigid-body model (thesis 2.5.1c: the whole body's dynamics, not a
/// cart-table). Velocities come from central differences of the samples on the configuration manifold
/// (Difference), the centroidal momentum h = [k_G; l] (CentroidalMomentum) is differenced again, and the ground
/// reaction that produces that rate of momentum, f = l' - m g and moment k_G' about the COM c, has zero horizontal
/// moment about the point p on the plane z = z_g:
///   p_x = c_x - ((c_z - z_g) f_x + k'_y) / f_z,   p_y = c_y - ((c_z - z_g) f_y - k'_x) / f_z.
/// For a pure translation with constant acceleration this is the cart-table ZMP x - (z_c / g) x''. At the first
/// and last sample one-sided differences are used. A sample with f_z <= 1e-6 m g (no support force, the robot in
/// the air) gets NaN.
///
/// `q` holds the samples (each of size nq, `period` s apart), `ground_height` z_g per sample (or one value for
/// all). Throws std::invalid_argument for fewer than 3 samples, a wrong size, a non-finite entry, a period that is
/// not positive and finite, or a ground_height vector whose size is neither 1 nor the number of samples.
std::vector<Eigen::Vector2d> ComputeMotionZmp(const multibody::Model& model, const std::vector<Eigen::VectorXd>& q,
                                              double period, const std::vector<double>& ground_height);

/// Velocities of the samples by central differences on the configuration manifold (one-sided at the ends), the
/// ones ComputeMotionZmp uses. Same checks.
std::vector<Eigen::VectorXd> SampleVelocities(const multibody::Model& model, const std::vector<Eigen::VectorXd>& q,
                                              double period);

}  // namespace cairn::planning
