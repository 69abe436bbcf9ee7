#include "cairn/perception/stereo/compute_confidence.h"

#include <cmath>
#include <limits>
#include <numeric>

#include "expect_throws.h"

namespace cairn::perception {
namespace {

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
