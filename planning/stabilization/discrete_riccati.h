#pragma once

#include <Eigen/Core>

namespace cairn::planning {

/// The stabilising solution P of the discrete algebraic Riccati equation
///   P = A^T P A - A^T P B (R + B^T P B)^-1 B^T P A + Q
/// by the structure-preserving doubling algorithm (Chu, Fan, Lin 2005): with A_0 = A, G_0 = B R^-1 B^T,
/// H_0 = Q and W_k = (I + G_k H_k)^-1,
///   A_k+1 = A_k W_k A_k,  G_k+1 = G_k + A_k W_k G_k A_k^T,  H_k+1 = H_k + A_k^T H_k W_k A_k,
/// H_k converges quadratically to P when (A, B) is stabilisable and (A, Q^1/2) detectable. Written here because
/// Eigen has no Riccati solver and the cart-table problem is small (4 x 4).
///
/// Throws std::invalid_argument for mismatched or non-finite matrices, a Q that is not symmetric positive
/// semidefinite or an R that is not symmetric positive definite; std::runtime_error if the iteration does not
/// converge within 100 doublings (the pair is not stabilisable).
Eigen::MatrixXd SolveDiscreteAlgebraicRiccati(const Eigen::MatrixXd& A, const Eigen::MatrixXd& B,
                                              const Eigen::MatrixXd& Q, const Eigen::MatrixXd& R);

}  // namespace cairn::planning
