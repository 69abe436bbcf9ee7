#pragma once

#include <string>

namespace cairn::perception {

/// Φ(x), the standard normal CDF.
double StandardNormalCdf(double x);
/// Φ⁻¹(p) for p in (0, 1), accurate to about 1e-15 (rational approximation refined by a Halley step).
double StandardNormalQuantile(double p);

/// The distribution of a material's coefficient of friction p(μ | label) (thesis eq. 3.9's F(μ | l_i)).
///
/// Kinds: normal (the thesis' Table 3.3), normal truncated to [0, ∞) (respects μ ≥ 0), generalized extreme
/// value (the thesis' own suggestion, 3.6.4, after measurements that fit it better) and "not walkable": all mass
/// at μ = 0 (sand, water, sky, ...: the robot must not step there).
class FrictionDistribution {
 public:
  enum class Kind { kNormal, kTruncatedNormal, kGeneralizedExtremeValue, kNotWalkable };

  /// N(mean, stddev²); stddev >= 0 (0 is a point mass at mean).
  static FrictionDistribution Normal(double mean, double stddev);
  /// N(mean, stddev²) conditioned on μ >= 0; stddev > 0.
  static FrictionDistribution TruncatedNormal(double mean, double stddev);
  /// GEV(location, scale, shape): F(μ) = exp(−(1 + shape (μ − location)/scale)^(−1/shape)); scale > 0.
  static FrictionDistribution GeneralizedExtremeValue(double location, double scale, double shape);
  /// All mass at μ = 0.
  static FrictionDistribution NotWalkable();

  Kind kind() const { return kind_; }
  /// "normal", "truncated_normal", "gev", "not_walkable".
  std::string kind_name() const;
  /// Parameters: (mean, stddev) for normals, (location, scale, shape) for GEV.
  double a() const { return a_; }
  double b() const { return b_; }
  double c() const { return c_; }
  bool walkable() const { return kind_ != Kind::kNotWalkable; }

  double Cdf(double mu) const;
  double Pdf(double mu) const;
  /// The p-quantile, p in (0, 1).
  double Quantile(double p) const;
  double Mean() const;
  double Variance() const;

 private:
  FrictionDistribution(Kind kind, double a, double b, double c) : kind_(kind), a_(a), b_(b), c_(c) {}
  Kind kind_;
  double a_, b_, c_;
};

/// Largest coefficient of friction a file may state. Rubber on dry rough ground reaches 1 to 2; 10 leaves room
/// for any real surface and refuses typos such as 1e6 (which would let every step through the chance constraint).
inline constexpr double kMaxFrictionCoefficient = 10.0;
/// Largest magnitude of a GEV shape a file may state (|shape| >= 1 already has no mean).
inline constexpr double kMaxGevShape = 5.0;

/// Throws std::invalid_argument, naming the parameter, its value and the range, unless `distribution` describes
/// physically meaningful friction: a mean or location in (0, kMaxFrictionCoefficient], a standard deviation or
/// scale of at most kMaxFrictionCoefficient, a GEV shape within +-kMaxGevShape. "Not walkable" always passes.
/// For values read from files (registries, scenarios); the factories above accept any finite parameters.
void CheckPhysicalFriction(const FrictionDistribution& distribution);

}  // namespace cairn::perception
