#pragma once

/// @file
/// Stereo confidence models defined over the whole disparity range (thesis section 4.3).

#include <optional>
#include <string>
#include <vector>

#include "cairn/perception/stereo/cost_volume_options.h"
#include "cairn/perception/stereo/histogram_sensor_model.h"

namespace cairn::perception {

/// The likelihood families p(E_d | d) of thesis section 4.3.
enum class ConfidenceModelType {
  /// Matthies: i.i.d. Gaussian (SSD, eq. 4.4) or Laplace (SAD/BTSAD, eq. 4.5) pixel differences.
  kMatthies,
  /// Merrell: costs Gaussian around the pixel's minimum cost (eq. 4.6).
  kMerrell,
  /// Exponentially distributed costs (eq. 4.7).
  kExponential,
  /// Histogram sensor model (eq. 4.12).
  kHistogram,
};

/// Parses "matthies", "merrell", "exp" or "hsm"; throws std::invalid_argument naming the value, the accepted
/// names and the closest one.
ConfidenceModelType ParseConfidenceModelType(const std::string& name);
/// "matthies", "merrell", "exp" or "hsm".
std::string ConfidenceModelTypeName(ConfidenceModelType type);

/// An immutable likelihood model p(E_d | d) of one cost function, from which the confidence
/// C(d) = p(E_d | d) / sum_d' p(E_d' | d') (eq. 4.3) is computed by ComputeConfidence().
///
/// The parameter is the one the thesis tabulates (Table 4.1): sigma^2_Mat (SSD) or b_Mat (SAD) for Matthies,
/// sigma^2_Mer for Merrell, mu for the exponential model. Matthies' window normalisation (sigma^2_Mat =
/// MN sigma_i^2, b_Mat = MN b_i) is folded into the parameter, so the model needs no window size.
class ConfidenceModel {
 public:
  /// Matthies' model for `cost`: log p = -SSD / (2 sigma2) for SSD, -SAD / sigma2 (= b_Mat) for BTSAD.
  static ConfidenceModel Matthies(CostFunction cost, double parameter);
  /// Merrell's model: log p = -(E - E_min)^2 / (2 sigma2).
  static ConfidenceModel Merrell(CostFunction cost, double sigma2);
  /// Exponential model: log p = -E / mu.
  static ConfidenceModel Exponential(CostFunction cost, double mu);
  /// Histogram sensor model: log p = log hist(E).
  static ConfidenceModel Histogram(CostFunction cost, HistogramSensorModel histogram);
  /// A parametric model (`type` other than kHistogram) with a fixed parameter; throws std::invalid_argument if
  /// the parameter is not positive and finite, or if `type` is kHistogram (use Histogram()).
  static ConfidenceModel Parametric(ConfidenceModelType type, CostFunction cost, double parameter);

  /// The maximum-likelihood model (thesis eqs. 4.8-4.11) from `samples`, the costs at trusted disparities
  /// (winner-take-all disparities that pass the left-right check, or ground truth): Matthies SSD
  /// sigma^2_Mat = sqrt(Var) / sqrt(2); Matthies SAD b_Mat = Mean; Merrell sigma^2 = Var; exponential mu = Mean;
  /// for kHistogram, a histogram trained on the samples (the thesis' "ML HSM"). Throws std::invalid_argument if
  /// there are fewer than two finite samples or they give a zero parameter.
  static ConfidenceModel FitMaximumLikelihood(ConfidenceModelType type, CostFunction cost,
                                              const std::vector<float>& samples);

  ConfidenceModelType type() const { return type_; }
  CostFunction cost_function() const { return cost_; }
  /// The model's parameter (see the class comment); NaN for the histogram model.
  double parameter() const { return parameter_; }
  /// The histogram of a kHistogram model, nullptr otherwise.
  const HistogramSensorModel* histogram() const { return histogram_ ? &*histogram_ : nullptr; }

  /// log p(E_d = cost | d) up to an additive constant per pixel; `min_cost` is the pixel's minimum cost (used by
  /// Merrell's model). Infinite costs give -infinity.
  double LogLikelihood(float cost, float min_cost) const;

  /// One-line description, e.g. "merrell(sigma2=1.2e+04)".
  std::string Describe() const;

 private:
  ConfidenceModel(ConfidenceModelType type, CostFunction cost, double parameter)
      : type_(type), cost_(cost), parameter_(parameter) {}

  ConfidenceModelType type_;
  CostFunction cost_;
  double parameter_;
  std::optional<HistogramSensorModel> histogram_;
};

}  // namespace cairn::perception
