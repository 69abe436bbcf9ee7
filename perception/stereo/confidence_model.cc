#include "cairn/common/number_text.h"
#include "cairn/perception/stereo/confidence_model.h"

#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "cairn/common/text_suggestions.h"

namespace cairn::perception {
namespace {

const std::vector<std::string>& ModelNames() {
  static const std::vector<std::string> names = {"matthies", "merrell", "exp", "hsm"};
  return names;
}

void CheckParameter(ConfidenceModelType type, double parameter) {
  if (!(parameter > 0.0) || !std::isfinite(parameter)) {
    std::ostringstream message;
    message << "confidence model '" << ConfidenceModelTypeName(type) << "' needs a positive, finite parameter, got "
            << parameter << "; pass a value such as the thesis' Table 4.1 entries, or estimate it by maximum "
            << "likelihood (--params ml)";
    throw std::invalid_argument(message.str());
  }
}

}  // namespace

ConfidenceModelType ParseConfidenceModelType(const std::string& name) {
  for (int i = 0; i < 4; ++i) {
    if (ModelNames()[i] == name) return static_cast<ConfidenceModelType>(i);
  }
  std::string message = "unknown confidence model '" + name + "'; expected one of " + QuotedList(ModelNames());
  const auto close = ClosestNames(name, ModelNames(), 1);
  if (!close.empty() && EditDistance(name, close.front()) <= 3) message += " (did you mean '" + close.front() + "'?)";
  throw std::invalid_argument(message);
}

std::string ConfidenceModelTypeName(ConfidenceModelType type) { return ModelNames()[static_cast<int>(type)]; }

ConfidenceModel ConfidenceModel::Matthies(CostFunction cost, double parameter) {
  CheckParameter(ConfidenceModelType::kMatthies, parameter);
  return ConfidenceModel(ConfidenceModelType::kMatthies, cost, parameter);
}

ConfidenceModel ConfidenceModel::Merrell(CostFunction cost, double sigma2) {
  CheckParameter(ConfidenceModelType::kMerrell, sigma2);
  return ConfidenceModel(ConfidenceModelType::kMerrell, cost, sigma2);
}

ConfidenceModel ConfidenceModel::Exponential(CostFunction cost, double mu) {
  CheckParameter(ConfidenceModelType::kExponential, mu);
  return ConfidenceModel(ConfidenceModelType::kExponential, cost, mu);
}

ConfidenceModel ConfidenceModel::Histogram(CostFunction cost, HistogramSensorModel histogram) {
  ConfidenceModel model(ConfidenceModelType::kHistogram, cost, std::numeric_limits<double>::quiet_NaN());
  model.histogram_ = std::move(histogram);
  return model;
}

ConfidenceModel ConfidenceModel::Parametric(ConfidenceModelType type, CostFunction cost, double parameter) {
  switch (type) {
    case ConfidenceModelType::kMatthies:
      return Matthies(cost, parameter);
    case ConfidenceModelType::kMerrell:
      return Merrell(cost, parameter);
    case ConfidenceModelType::kExponential:
      return Exponential(cost, parameter);
    case ConfidenceModelType::kHistogram:
      break;
  }
  throw std::invalid_argument(
      "the histogram sensor model ('hsm') has no scalar parameter; train it from costs (--params ml, or "
      "HistogramSensorModel::FromSamples) instead of passing a value");
}

ConfidenceModel ConfidenceModel::FitMaximumLikelihood(ConfidenceModelType type, CostFunction cost,
                                                      const std::vector<float>& samples) {
  if (type == ConfidenceModelType::kHistogram) return Histogram(cost, HistogramSensorModel::FromSamples(samples));
  double sum = 0.0;
  std::size_t n = 0;
  for (float s : samples) {
    if (!std::isfinite(s)) continue;
    sum += s;
    ++n;
  }
  if (n < 2) {
    throw std::invalid_argument("maximum-likelihood fit of '" + ConfidenceModelTypeName(type) + "' got " +
                                cairn::FormatShort(n) +
                                " finite cost samples; the left-right check rejected (almost) every pixel, so "
                                "check that the images are a rectified pair and the disparity range covers the scene");
  }
  const double mean = sum / static_cast<double>(n);
  double squares = 0.0;
  for (float s : samples) {
    if (std::isfinite(s)) squares += (s - mean) * (s - mean);
  }
  const double variance = squares / static_cast<double>(n);
  double parameter = 0.0;
  switch (type) {
    case ConfidenceModelType::kMatthies:
      // eq. 4.8 times MN (SSD), eq. 4.9 times MN (SAD): the window normalisation cancels.
      parameter = cost == CostFunction::kSsd ? std::sqrt(variance) / std::sqrt(2.0) : mean;
      break;
    case ConfidenceModelType::kMerrell:
      parameter = variance;  // eq. 4.10
      break;
    case ConfidenceModelType::kExponential:
      parameter = mean;  // eq. 4.11
      break;
    case ConfidenceModelType::kHistogram:
      break;
  }
  return Parametric(type, cost, parameter);
}

double ConfidenceModel::LogLikelihood(float cost, float min_cost) const {
  if (!std::isfinite(cost)) return -std::numeric_limits<double>::infinity();
  const double e = cost;
  switch (type_) {
    case ConfidenceModelType::kMatthies:
      return cost_ == CostFunction::kSsd ? -e / (2.0 * parameter_) : -e / parameter_;
    case ConfidenceModelType::kMerrell: {
      const double r = e - static_cast<double>(min_cost);
      return -r * r / (2.0 * parameter_);
    }
    case ConfidenceModelType::kExponential:
      return -e / parameter_;
    case ConfidenceModelType::kHistogram:
      return histogram_->LogDensity(cost);
  }
  return 0.0;
}

std::string ConfidenceModel::Describe() const {
  std::ostringstream out;
  out.precision(4);
  out << ConfidenceModelTypeName(type_) << "(" << CostFunctionName(cost_) << ", ";
  switch (type_) {
    case ConfidenceModelType::kMatthies:
      out << (cost_ == CostFunction::kSsd ? "sigma2=" : "b=") << parameter_;
      break;
    case ConfidenceModelType::kMerrell:
      out << "sigma2=" << parameter_;
      break;
    case ConfidenceModelType::kExponential:
      out << "mu=" << parameter_;
      break;
    case ConfidenceModelType::kHistogram:
      out << histogram_->counts().size() << " bins of width " << histogram_->bin_width() << ", "
          << histogram_->num_samples() << " samples";
      break;
  }
  out << ")";
  return out.str();
}

}  // namespace cairn::perception
