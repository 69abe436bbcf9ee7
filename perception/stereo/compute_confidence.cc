#include "cairn/perception/stereo/compute_confidence.h"

#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

#include "cairn/common/cairn_assert.h"
#include "cairn/common/parallel_for.h"
#include "cairn/perception/stereo/internal/fast_exp.h"

namespace cairn::perception {

void ComputeConfidence(const DisparityVolume& costs, const ConfidenceModel& model, DisparityVolume* confidence,
                       int num_threads) {
  CAIRN_CHECK(confidence != nullptr);
  CAIRN_CHECK(confidence != &costs);
  if (costs.num_disparities() == 0) {
    throw std::invalid_argument("ComputeConfidence: the cost volume is empty; run ComputeCostVolume() first");
  }
  confidence->Resize(costs.height(), costs.width(), costs.min_disparity(), costs.max_disparity());
  const int width = costs.width();
  const int num_disp = costs.num_disparities();
  const ConfidenceModelType type = model.type();
  const bool ssd = model.cost_function() == CostFunction::kSsd;
  const double parameter = model.parameter();
  // The parametric models are log p = -a * E (Matthies, exponential) or -a * (E - E_min)^2 (Merrell).
  double a = 0.0;
  if (type == ConfidenceModelType::kMatthies) a = ssd ? 1.0 / (2.0 * parameter) : 1.0 / parameter;
  if (type == ConfidenceModelType::kExponential) a = 1.0 / parameter;
  if (type == ConfidenceModelType::kMerrell) a = 1.0 / (2.0 * parameter);
  const auto fa = static_cast<float>(a);
  const HistogramSensorModel* histogram = model.histogram();
  constexpr float kInfinity = std::numeric_limits<float>::infinity();

  ParallelFor(costs.height(), num_threads, [&](int, int y0, int y1) {
    std::vector<float> log_p(num_disp);
    for (int y = y0; y < y1; ++y) {
      for (int x = 0; x < width; ++x) {
        const float* c = costs.curve(y, x);
        float* out = confidence->mutable_curve(y, x);
        float min_cost = std::numeric_limits<float>::infinity();
#pragma omp simd reduction(min : min_cost)
        for (int k = 0; k < num_disp; ++k) min_cost = std::min(min_cost, c[k]);
        if (!std::isfinite(min_cost)) {
          for (int k = 0; k < num_disp; ++k) out[k] = 0.0f;
          continue;
        }
        // Shift by the largest log-likelihood before exponentiating (log-sum-exp).
        float max_log = 0.0f;
        switch (type) {
          case ConfidenceModelType::kMatthies:
          case ConfidenceModelType::kExponential:
            for (int k = 0; k < num_disp; ++k) log_p[k] = -fa * (c[k] - min_cost);
            break;
          case ConfidenceModelType::kMerrell:
            for (int k = 0; k < num_disp; ++k) {
              const float r = c[k] - min_cost;
              log_p[k] = -fa * r * r;
            }
            break;
          case ConfidenceModelType::kHistogram:
            max_log = -std::numeric_limits<float>::infinity();
            for (int k = 0; k < num_disp; ++k) {
              log_p[k] = static_cast<float>(histogram->LogDensity(c[k]));
              max_log = std::max(max_log, log_p[k]);
            }
            break;
        }
        // Infinite costs give -inf (or NaN from inf - inf in Merrell's square); both must become probability 0.
        float sum = 0.0f;
#pragma omp simd reduction(+ : sum)
        for (int k = 0; k < num_disp; ++k) {
          const float v = c[k] < kInfinity ? internal::ExpNonPositive(log_p[k] - max_log) : 0.0f;
          out[k] = v;
          sum += v;
        }
        const float inverse = 1.0f / sum;
        for (int k = 0; k < num_disp; ++k) out[k] *= inverse;
      }
    }
  });
}

}  // namespace cairn::perception
