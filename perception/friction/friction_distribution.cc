#include "cairn/perception/friction/friction_distribution.h"
#include "cairn/common/number_text.h"

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace cairn::perception {
namespace {

constexpr double kInvSqrt2 = 0.70710678118654752440;
constexpr double kInvSqrt2Pi = 0.39894228040143267794;
// Euler–Mascheroni constant, for the GEV mean with shape 0.
constexpr double kEulerGamma = 0.57721566490153286061;

void CheckFinite(const char* what, double value) {
  if (!std::isfinite(value)) {
    throw std::invalid_argument(std::string("Friction distribution: ") + what + " must be finite; got " +
                                FormatShort(value) + ".");
  }
}

}  // namespace

double StandardNormalCdf(double x) { return 0.5 * std::erfc(-x * kInvSqrt2); }

double StandardNormalQuantile(double p) {
  if (!(p > 0.0 && p < 1.0)) {
    throw std::invalid_argument("StandardNormalQuantile: p must be in (0, 1); got " + FormatShort(p) + ".");
  }
  // Acklam's rational approximation (relative error 1.15e-9) ...
  static const double a[] = {-3.969683028665376e+01, 2.209460984245205e+02, -2.759285104469687e+02,
                             1.383577518672690e+02,  -3.066479806614716e+01, 2.506628277459239e+00};
  static const double b[] = {-5.447609879822406e+01, 1.615858368580409e+02, -1.556989798598866e+02,
                             6.680131188771972e+01,  -1.328068155288572e+01};
  static const double c[] = {-7.784894002430293e-03, -3.223964580411365e-01, -2.400758277161838e+00,
                             -2.549732539343734e+00, 4.374664141464968e+00,  2.938163982698783e+00};
  static const double d[] = {7.784695709041462e-03, 3.224671290700398e-01, 2.445134137142996e+00,
                             3.754408661907416e+00};
  const double p_low = 0.02425;
  double x;
  if (p < p_low) {
    const double q = std::sqrt(-2.0 * std::log(p));
    x = (((((c[0] * q + c[1]) * q + c[2]) * q + c[3]) * q + c[4]) * q + c[5]) /
        ((((d[0] * q + d[1]) * q + d[2]) * q + d[3]) * q + 1.0);
  } else if (p <= 1.0 - p_low) {
    const double q = p - 0.5;
    const double r = q * q;
    x = (((((a[0] * r + a[1]) * r + a[2]) * r + a[3]) * r + a[4]) * r + a[5]) * q /
        (((((b[0] * r + b[1]) * r + b[2]) * r + b[3]) * r + b[4]) * r + 1.0);
  } else {
    const double q = std::sqrt(-2.0 * std::log1p(-p));
    x = -(((((c[0] * q + c[1]) * q + c[2]) * q + c[3]) * q + c[4]) * q + c[5]) /
        ((((d[0] * q + d[1]) * q + d[2]) * q + d[3]) * q + 1.0);
  }
  // ... refined by one Halley step on Φ(x) − p, which brings it to full double precision.
  const double e = StandardNormalCdf(x) - p;
  const double u = e * std::sqrt(2.0 * M_PI) * std::exp(0.5 * x * x);
  return x - u / (1.0 + 0.5 * x * u);
}

FrictionDistribution FrictionDistribution::Normal(double mean, double stddev) {
  CheckFinite("the mean", mean);
  CheckFinite("the standard deviation", stddev);
  if (stddev < 0.0) {
    throw std::invalid_argument("Friction distribution: the standard deviation must be >= 0; got " +
                                FormatShort(stddev) + ".");
  }
  return FrictionDistribution(Kind::kNormal, mean, stddev, 0.0);
}

FrictionDistribution FrictionDistribution::TruncatedNormal(double mean, double stddev) {
  CheckFinite("the mean", mean);
  CheckFinite("the standard deviation", stddev);
  if (!(stddev > 0.0)) {
    throw std::invalid_argument("Friction distribution: a truncated normal needs a standard deviation > 0; got " +
                                FormatShort(stddev) + ".");
  }
  if (StandardNormalCdf(mean / stddev) < 1e-12) {
    throw std::invalid_argument("Friction distribution: a normal with mean " + FormatShort(mean) + " and deviation " +
                                FormatShort(stddev) + " has no mass on [0, inf) to truncate to; raise the mean.");
  }
  return FrictionDistribution(Kind::kTruncatedNormal, mean, stddev, 0.0);
}

FrictionDistribution FrictionDistribution::GeneralizedExtremeValue(double location, double scale, double shape) {
  CheckFinite("the location", location);
  CheckFinite("the scale", scale);
  CheckFinite("the shape", shape);
  if (!(scale > 0.0)) {
    throw std::invalid_argument("Friction distribution: the GEV scale must be > 0; got " + FormatShort(scale) + ".");
  }
  return FrictionDistribution(Kind::kGeneralizedExtremeValue, location, scale, shape);
}

void CheckPhysicalFriction(const FrictionDistribution& distribution) {
  auto check = [](const char* what, double value, double lo, bool lo_open, double hi) {
    if (!(lo_open ? value > lo : value >= lo) || !(value <= hi)) {
      throw std::invalid_argument(std::string("Friction distribution: ") + what + " " + FormatShort(value) +
                                  " is outside " + (lo_open ? "(" : "[") + FormatShort(lo) + ", " + FormatShort(hi) +
                                  "]; a coefficient of friction is at most " + FormatShort(kMaxFrictionCoefficient) +
                                  " (use not_walkable for ground no foot may use).");
    }
  };
  switch (distribution.kind()) {
    case FrictionDistribution::Kind::kNormal:
    case FrictionDistribution::Kind::kTruncatedNormal:
      check("the mean", distribution.a(), 0.0, true, kMaxFrictionCoefficient);
      check("the standard deviation", distribution.b(), 0.0, false, kMaxFrictionCoefficient);
      break;
    case FrictionDistribution::Kind::kGeneralizedExtremeValue:
      check("the location", distribution.a(), 0.0, true, kMaxFrictionCoefficient);
      check("the scale", distribution.b(), 0.0, true, kMaxFrictionCoefficient);
      check("the shape", distribution.c(), -kMaxGevShape, false, kMaxGevShape);
      break;
    case FrictionDistribution::Kind::kNotWalkable:
      break;
  }
}

FrictionDistribution FrictionDistribution::NotWalkable() { return FrictionDistribution(Kind::kNotWalkable, 0, 0, 0); }

std::string FrictionDistribution::kind_name() const {
  switch (kind_) {
    case Kind::kNormal: return "normal";
    case Kind::kTruncatedNormal: return "truncated_normal";
    case Kind::kGeneralizedExtremeValue: return "gev";
    case Kind::kNotWalkable: return "not_walkable";
  }
  return "";
}

double FrictionDistribution::Cdf(double mu) const {
  switch (kind_) {
    case Kind::kNormal:
      if (b_ == 0.0) return mu >= a_ ? 1.0 : 0.0;
      return StandardNormalCdf((mu - a_) / b_);
    case Kind::kTruncatedNormal: {
      if (mu <= 0.0) return 0.0;
      const double below = StandardNormalCdf(-a_ / b_);
      return (StandardNormalCdf((mu - a_) / b_) - below) / (1.0 - below);
    }
    case Kind::kGeneralizedExtremeValue: {
      const double z = (mu - a_) / b_;
      if (c_ == 0.0) return std::exp(-std::exp(-z));
      const double t = 1.0 + c_ * z;
      if (t <= 0.0) return c_ > 0.0 ? 0.0 : 1.0;  // Outside the support: below it for shape > 0, above for < 0.
      return std::exp(-std::pow(t, -1.0 / c_));
    }
    case Kind::kNotWalkable:
      return mu >= 0.0 ? 1.0 : 0.0;
  }
  return 0.0;
}

double FrictionDistribution::Pdf(double mu) const {
  switch (kind_) {
    case Kind::kNormal: {
      if (b_ == 0.0) return mu == a_ ? std::numeric_limits<double>::infinity() : 0.0;
      const double z = (mu - a_) / b_;
      return kInvSqrt2Pi / b_ * std::exp(-0.5 * z * z);
    }
    case Kind::kTruncatedNormal: {
      if (mu < 0.0) return 0.0;
      const double z = (mu - a_) / b_;
      return kInvSqrt2Pi / b_ * std::exp(-0.5 * z * z) / (1.0 - StandardNormalCdf(-a_ / b_));
    }
    case Kind::kGeneralizedExtremeValue: {
      const double z = (mu - a_) / b_;
      if (c_ == 0.0) return std::exp(-z) * std::exp(-std::exp(-z)) / b_;
      const double t = 1.0 + c_ * z;
      if (t <= 0.0) return 0.0;
      const double power = std::pow(t, -1.0 / c_);
      return power / t * std::exp(-power) / b_;
    }
    case Kind::kNotWalkable:
      return mu == 0.0 ? std::numeric_limits<double>::infinity() : 0.0;
  }
  return 0.0;
}

double FrictionDistribution::Quantile(double p) const {
  if (!(p > 0.0 && p < 1.0)) {
    throw std::invalid_argument("FrictionDistribution::Quantile: p must be in (0, 1); got " + FormatShort(p) + ".");
  }
  switch (kind_) {
    case Kind::kNormal:
      return a_ + b_ * StandardNormalQuantile(p);
    case Kind::kTruncatedNormal: {
      const double below = StandardNormalCdf(-a_ / b_);
      return a_ + b_ * StandardNormalQuantile(below + p * (1.0 - below));
    }
    case Kind::kGeneralizedExtremeValue: {
      const double y = -std::log(p);
      if (c_ == 0.0) return a_ - b_ * std::log(y);
      return a_ + b_ * (std::pow(y, -c_) - 1.0) / c_;
    }
    case Kind::kNotWalkable:
      return 0.0;
  }
  return 0.0;
}

double FrictionDistribution::Mean() const {
  switch (kind_) {
    case Kind::kNormal: return a_;
    case Kind::kTruncatedNormal: {
      const double alpha = -a_ / b_;
      const double lambda = kInvSqrt2Pi * std::exp(-0.5 * alpha * alpha) / (1.0 - StandardNormalCdf(alpha));
      return a_ + b_ * lambda;
    }
    case Kind::kGeneralizedExtremeValue:
      if (c_ == 0.0) return a_ + b_ * kEulerGamma;
      if (c_ >= 1.0) return std::numeric_limits<double>::infinity();
      return a_ + b_ * (std::tgamma(1.0 - c_) - 1.0) / c_;
    case Kind::kNotWalkable: return 0.0;
  }
  return 0.0;
}

double FrictionDistribution::Variance() const {
  switch (kind_) {
    case Kind::kNormal: return b_ * b_;
    case Kind::kTruncatedNormal: {
      const double alpha = -a_ / b_;
      const double lambda = kInvSqrt2Pi * std::exp(-0.5 * alpha * alpha) / (1.0 - StandardNormalCdf(alpha));
      return b_ * b_ * (1.0 + alpha * lambda - lambda * lambda);
    }
    case Kind::kGeneralizedExtremeValue: {
      if (c_ == 0.0) return b_ * b_ * M_PI * M_PI / 6.0;
      if (c_ >= 0.5) return std::numeric_limits<double>::infinity();
      const double g1 = std::tgamma(1.0 - c_);
      const double g2 = std::tgamma(1.0 - 2.0 * c_);
      return b_ * b_ * (g2 - g1 * g1) / (c_ * c_);
    }
    case Kind::kNotWalkable: return 0.0;
  }
  return 0.0;
}

}  // namespace cairn::perception
