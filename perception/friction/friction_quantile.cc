#include "cairn/perception/friction/friction_quantile.h"
#include "cairn/common/number_text.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace cairn::perception {
namespace {

// No coefficient of friction of a walkable surface comes near this; a search reaching it means the mixture is
// malformed (e.g. a GEV with a heavy upper tail at the quantile asked for).
constexpr double kMaxFriction = 100.0;
// Smallest step of the uniform search: a million CDF evaluations per pixel up to kMaxFriction.
constexpr double kMinSearchStep = kMaxFriction / 1e6;

double Cdf(const MaterialRegistry& registry, const Eigen::Ref<const Eigen::VectorXd>& p, double mu) {
  double value = 0.0;
  for (int i = 0; i < registry.size(); ++i) {
    if (p[i] != 0.0) value += p[i] * registry.material(i).friction.Cdf(mu);
  }
  return value;
}

double SearchQuantile(const MaterialRegistry& registry, const Eigen::Ref<const Eigen::VectorXd>& p, double target,
                      double step) {
  double quantile = 0.0;
  for (long k = 0;; ++k) {
    const double mu = static_cast<double>(k) * step;
    if (mu > kMaxFriction) {
      throw std::invalid_argument("Friction quantile search passed mu = " + FormatShort(kMaxFriction) +
                                  " without reaching the quantile; check the registry's distributions.");
    }
    if (Cdf(registry, p, mu) > target) return quantile;
    quantile = mu;
  }
}

double ExactQuantile(const MaterialRegistry& registry, const Eigen::Ref<const Eigen::VectorXd>& p, double target,
                     double tolerance) {
  if (Cdf(registry, p, 0.0) >= target) return 0.0;
  // The mixture's quantile lies between its components' quantiles.
  double high = 0.0;
  for (int i = 0; i < registry.size(); ++i) {
    if (p[i] != 0.0) high = std::max(high, registry.material(i).friction.Quantile(target));
  }
  double low = 0.0;
  high = std::max(high, tolerance);
  while (high - low > tolerance) {
    const double middle = 0.5 * (low + high);
    if (middle <= low || middle >= high) break;  // a tolerance below the doubles' resolution: as close as it gets
    (Cdf(registry, p, middle) >= target ? high : low) = middle;
  }
  return 0.5 * (low + high);
}

double GaussianQuantile(const MaterialRegistry& registry, const Eigen::Ref<const Eigen::VectorXd>& p, double target) {
  double mean = 0.0;
  double second = 0.0;
  for (int i = 0; i < registry.size(); ++i) {
    if (p[i] == 0.0) continue;
    const FrictionDistribution& f = registry.material(i).friction;
    const double m = f.Mean();
    mean += p[i] * m;
    second += p[i] * (f.Variance() + m * m);
  }
  const double deviation = std::sqrt(std::max(second - mean * mean, 0.0));
  return std::max(0.0, mean + deviation * StandardNormalQuantile(target));
}

void CheckArguments(double eta, QuantileMethod method, double tolerance) {
  if (!(eta > 0.0 && eta < 1.0)) {
    throw std::invalid_argument("eta (the probability that friction is at least the quantile) must be in (0, 1); "
                                "got " + FormatShort(eta) + ". The thesis uses 0.95.");
  }
  if (!(tolerance > 0.0) || !std::isfinite(tolerance)) {
    throw std::invalid_argument("The quantile tolerance must be finite and > 0; got " + FormatShort(tolerance) + ".");
  }
  // The uniform search takes up to kMaxFriction / tolerance steps per pixel.
  if (method == QuantileMethod::kSearch && tolerance < kMinSearchStep) {
    throw std::invalid_argument("The quantile search step " + FormatShort(tolerance) + " is below " +
                                FormatShort(kMinSearchStep) + ", which already takes " +
                                FormatShort(kMaxFriction / kMinSearchStep) +
                                " steps per pixel; use a larger step or the exact method.");
  }
}

double QuantileOfValidated(const MaterialRegistry& registry, const Eigen::Ref<const Eigen::VectorXd>& p, double eta,
                           QuantileMethod method, double tolerance) {
  const double target = 1.0 - eta;
  switch (method) {
    case QuantileMethod::kSearch: return SearchQuantile(registry, p, target, tolerance);
    case QuantileMethod::kExact: return ExactQuantile(registry, p, target, tolerance);
    case QuantileMethod::kGaussian: return GaussianQuantile(registry, p, target);
  }
  return 0.0;
}

}  // namespace

double MixtureCdf(const MaterialRegistry& registry, const Eigen::Ref<const Eigen::VectorXd>& probabilities,
                  double mu) {
  registry.ValidateProbabilities(probabilities);
  return Cdf(registry, probabilities, mu);
}

double FrictionQuantile(const MaterialRegistry& registry, const Eigen::Ref<const Eigen::VectorXd>& probabilities,
                        double eta, QuantileMethod method, double tolerance) {
  CheckArguments(eta, method, tolerance);
  registry.ValidateProbabilities(probabilities);
  return QuantileOfValidated(registry, probabilities, eta, method, tolerance);
}

Eigen::VectorXd FrictionQuantiles(const MaterialRegistry& registry,
                                  const Eigen::Ref<const Eigen::MatrixXd>& probabilities, double eta,
                                  QuantileMethod method, double tolerance) {
  CheckArguments(eta, method, tolerance);
  Eigen::VectorXd quantiles(probabilities.rows());
  Eigen::VectorXd row(probabilities.cols());
  for (Eigen::Index k = 0; k < probabilities.rows(); ++k) {
    row = probabilities.row(k).transpose();
    try {
      registry.ValidateProbabilities(row);
    } catch (const std::invalid_argument& error) {
      throw std::invalid_argument("Pixel " + cairn::FormatShort(k) + ": " + error.what());
    }
    quantiles[k] = QuantileOfValidated(registry, row, eta, method, tolerance);
  }
  return quantiles;
}

}  // namespace cairn::perception
