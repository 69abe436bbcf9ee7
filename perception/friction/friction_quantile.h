#pragma once

#include <Eigen/Core>

#include "cairn/perception/friction/material_registry.h"

namespace cairn::perception {

/// How to find the friction quantile of a pixel's mixture.
enum class QuantileMethod {
  kSearch,    ///< The thesis' Algorithm 1 (chapter 5): uniform search from μ = 0 in steps of the tolerance.
  kExact,     ///< Bisection on the mixture CDF to the tolerance.
  kGaussian,  ///< One Gaussian with the mixture's mean and variance (the thesis' faster, cruder alternative).
};

/// F(μ) = Σ_i P(x = l_i) F(μ | l_i), the per-pixel mixture CDF (thesis eq. 3.9). Probabilities are validated.
double MixtureCdf(const MaterialRegistry& registry, const Eigen::Ref<const Eigen::VectorXd>& probabilities, double mu);

/// The lower friction bound Q_{1−η}: friction is at least Q with probability η (thesis eq. 5.3's quantile).
/// Friction is non-negative, so mixture mass below 0 (normal tails, not-walkable labels) counts as μ = 0 and the
/// result is never negative: Q = inf{μ >= 0 : F(μ) >= 1 − η}.
///
/// kSearch returns the largest grid value k·tolerance with F <= 1 − η (so Q − tolerance < result <= Q, as
/// Algorithm 1); kExact is within tolerance of Q; kGaussian is max(0, m + s Φ⁻¹(1 − η)) for the mixture's mean
/// m and deviation s. Throws std::invalid_argument for η outside (0, 1), tolerance <= 0, or a kSearch step below
/// 1e-4 (a million steps up to μ = 100). kExact stops at the doubles' resolution when the tolerance is below it.
double FrictionQuantile(const MaterialRegistry& registry, const Eigen::Ref<const Eigen::VectorXd>& probabilities,
                        double eta, QuantileMethod method, double tolerance = 1e-4);

/// FrictionQuantile() for every row of `probabilities` (pixels x labels).
Eigen::VectorXd FrictionQuantiles(const MaterialRegistry& registry,
                                  const Eigen::Ref<const Eigen::MatrixXd>& probabilities, double eta,
                                  QuantileMethod method, double tolerance = 1e-4);

}  // namespace cairn::perception
