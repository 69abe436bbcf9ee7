#include "cairn/perception/stereo/confidence_model.h"

#include <cmath>
#include <stdexcept>

#include "expect_throws.h"

namespace cairn::perception {
namespace {

TEST(ConfidenceModelTest, LogLikelihoodsFollowTheThesisEquations) {
  EXPECT_DOUBLE_EQ(ConfidenceModel::Matthies(CostFunction::kSsd, 4.0).LogLikelihood(10.0f, 2.0f), -10.0 / 8.0);
  EXPECT_DOUBLE_EQ(ConfidenceModel::Matthies(CostFunction::kBtSad, 4.0).LogLikelihood(10.0f, 2.0f), -10.0 / 4.0);
  EXPECT_DOUBLE_EQ(ConfidenceModel::Merrell(CostFunction::kSsd, 4.0).LogLikelihood(10.0f, 2.0f), -64.0 / 8.0);
  EXPECT_DOUBLE_EQ(ConfidenceModel::Exponential(CostFunction::kSsd, 5.0).LogLikelihood(10.0f, 2.0f), -2.0);
  EXPECT_TRUE(std::isinf(ConfidenceModel::Exponential(CostFunction::kSsd, 5.0)
                             .LogLikelihood(std::numeric_limits<float>::infinity(), 0.0f)));
}

TEST(ConfidenceModelTest, MaximumLikelihoodParameters) {
  const std::vector<float> samples = {1.0f, 3.0f, 5.0f, 7.0f};  // mean 4, variance 5
  using T = ConfidenceModelType;
  EXPECT_DOUBLE_EQ(ConfidenceModel::FitMaximumLikelihood(T::kExponential, CostFunction::kSsd, samples).parameter(), 4.0);
  EXPECT_DOUBLE_EQ(ConfidenceModel::FitMaximumLikelihood(T::kMerrell, CostFunction::kSsd, samples).parameter(), 5.0);
  EXPECT_DOUBLE_EQ(ConfidenceModel::FitMaximumLikelihood(T::kMatthies, CostFunction::kSsd, samples).parameter(),
                   std::sqrt(5.0) / std::sqrt(2.0));
  // With a SAD cost the ML Matthies model equals the ML exponential model (thesis, after eq. 4.9).
  EXPECT_DOUBLE_EQ(ConfidenceModel::FitMaximumLikelihood(T::kMatthies, CostFunction::kBtSad, samples).parameter(), 4.0);
  const auto hsm = ConfidenceModel::FitMaximumLikelihood(T::kHistogram, CostFunction::kBtSad, samples);
  ASSERT_NE(hsm.histogram(), nullptr);
  EXPECT_EQ(hsm.histogram()->num_samples(), 4u);
  EXPECT_THAT(hsm.Describe(), ::testing::HasSubstr("hsm(btsad"));
}

TEST(ConfidenceModelTest, ErrorsNameTheValueAndTheFix) {
  CAIRN_EXPECT_THROWS_WITH(ParseConfidenceModelType("merel"), std::invalid_argument, "'merel'",
                           "did you mean 'merrell'");
  CAIRN_EXPECT_THROWS_WITH(ConfidenceModel::Merrell(CostFunction::kSsd, -1.0), std::invalid_argument, "-1",
                           "maximum likelihood");
  CAIRN_EXPECT_THROWS_WITH(ConfidenceModel::Parametric(ConfidenceModelType::kHistogram, CostFunction::kSsd, 1.0),
                           std::invalid_argument, "no scalar parameter");
  CAIRN_EXPECT_THROWS_WITH(
      ConfidenceModel::FitMaximumLikelihood(ConfidenceModelType::kMerrell, CostFunction::kSsd, {1.0f}),
      std::invalid_argument, "got 1 finite cost samples", "rectified");
  EXPECT_EQ(ConfidenceModelTypeName(ParseConfidenceModelType("exp")), "exp");
}

}  // namespace
}  // namespace cairn::perception
