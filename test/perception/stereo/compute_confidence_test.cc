#include "cairn/perception/stereo/compute_confidence.h"

#include <cmath>
#include <limits>
#include <numeric>

#include "cairn/perception/occupancy/internal/fast_log.h"
#include "cairn/perception/stereo/internal/fast_exp.h"
#include "expect_throws.h"

namespace cairn::perception {
namespace {

// The vectorisable exp used by ComputeConfidence() against std::exp over its whole domain.
TEST(ComputeConfidenceTest, FastExpMatchesStdExp) {
  double worst = 0.0;
  for (float x = 0.0f; x > -87.0f; x -= 0.001237f) {
    const double reference = std::exp(static_cast<double>(x));
    worst = std::max(worst, std::abs(internal::ExpNonPositive(x) - reference) / reference);
  }
  EXPECT_LT(worst, 5e-7);
  EXPECT_EQ(internal::ExpNonPositive(0.0f), 1.0f);
  EXPECT_LT(internal::ExpNonPositive(-1.0e6f), 1e-37f);
  EXPECT_LT(internal::ExpNonPositive(std::numeric_limits<float>::quiet_NaN()), 1e-37f);
}

// The logarithm of the occupancy update's log-odds against std::log, over the probability clamps' range and more.
TEST(ComputeConfidenceTest, FastLogMatchesStdLog) {
  double worst = 0.0;
  for (float x = 1e-4f; x < 1e4f; x *= 1.0007f) {
    worst = std::max(worst, std::abs(internal::LogPositive(x) - std::log(static_cast<double>(x))));
  }
  EXPECT_LT(worst, 2e-6);
  EXPECT_EQ(internal::LogPositive(1.0f), 0.0f);
}

TEST(ComputeConfidenceTest, NormalisedLikelihoodsEvenWhenExpUnderflows) {
  DisparityVolume costs(1, 3, 0, 3);
  const float a[4] = {2.0f, 1.0f, 3.0f, std::numeric_limits<float>::infinity()};
  const float huge[4] = {1.0e6f, 1.0e6f + 2.0f, 1.0e6f + 1.0f, 1.0e6f + 5.0f};  // exp(-1e6) underflows
  std::copy(a, a + 4, costs.mutable_curve(0, 0));
  std::copy(huge, huge + 4, costs.mutable_curve(0, 1));
  for (int k = 0; k < 4; ++k) costs.mutable_curve(0, 2)[k] = std::numeric_limits<float>::infinity();
  const auto model = ConfidenceModel::Exponential(CostFunction::kSsd, 1.0);
  DisparityVolume confidence;
  ComputeConfidence(costs, model, &confidence, 2);
  const double z = std::exp(-2.0) + std::exp(-1.0) + std::exp(-3.0);
  EXPECT_NEAR(confidence.at(0, 0, 0), std::exp(-2.0) / z, 1e-6);
  EXPECT_NEAR(confidence.at(0, 0, 1), std::exp(-1.0) / z, 1e-6);
  EXPECT_EQ(confidence.at(0, 0, 3), 0.0f);
  const double z2 = 1.0 + std::exp(-2.0) + std::exp(-1.0) + std::exp(-5.0);
  EXPECT_NEAR(confidence.at(0, 1, 0), 1.0 / z2, 1e-6);
  EXPECT_NEAR(confidence.at(0, 1, 2), std::exp(-1.0) / z2, 1e-6);
  for (int k = 0; k < 4; ++k) EXPECT_EQ(confidence.at(0, 2, k), 0.0f);
}

TEST(ComputeConfidenceTest, EveryModelGivesADistribution) {
  DisparityVolume costs(2, 2, 0, 9);
  for (int y = 0; y < 2; ++y)
    for (int x = 0; x < 2; ++x)
      for (int k = 0; k < 10; ++k) costs.mutable_curve(y, x)[k] = static_cast<float>(100 + 37 * ((k * 7 + x + y) % 10));
  std::vector<float> samples = {100, 120, 90, 150, 110, 130, 95};
  for (auto type : {ConfidenceModelType::kMatthies, ConfidenceModelType::kMerrell, ConfidenceModelType::kExponential,
                    ConfidenceModelType::kHistogram}) {
    const auto model = ConfidenceModel::FitMaximumLikelihood(type, CostFunction::kSsd, samples);
    DisparityVolume confidence;
    ComputeConfidence(costs, model, &confidence);
    for (int y = 0; y < 2; ++y) {
      for (int x = 0; x < 2; ++x) {
        const float* c = confidence.curve(y, x);
        EXPECT_NEAR(std::accumulate(c, c + 10, 0.0), 1.0, 1e-5) << ConfidenceModelTypeName(type);
        // Lower costs never get less confidence (every model is monotone on these costs but the HSM).
        if (type != ConfidenceModelType::kHistogram) {
          const float* e = costs.curve(y, x);
          for (int k = 1; k < 10; ++k) EXPECT_EQ(e[k] < e[k - 1], c[k] > c[k - 1]);
        }
      }
    }
  }
  DisparityVolume confidence;
  CAIRN_EXPECT_THROWS_WITH(ComputeConfidence(DisparityVolume(), ConfidenceModel::Merrell(CostFunction::kSsd, 1.0),
                                             &confidence),
                           std::invalid_argument, "empty");
}

}  // namespace
}  // namespace cairn::perception
