#include "cairn/perception/stereo/histogram_sensor_model.h"

#include <cmath>
#include <random>
#include <stdexcept>

#include "expect_throws.h"

namespace cairn::perception {
namespace {

TEST(HistogramSensorModelTest, UsesScottsBinWidthAndNormalises) {
  std::mt19937 rng(3);
  std::normal_distribution<float> cost(50.0f, 10.0f);
  std::vector<float> samples(8000);
  for (float& s : samples) s = std::max(0.0f, cost(rng));
  const auto model = HistogramSensorModel::FromSamples(samples);
  EXPECT_EQ(model.num_samples(), 8000u);
  EXPECT_NEAR(model.bin_width(), 3.5 * 10.0 / 20.0, 0.1);  // 8000^(1/3) = 20
  // The density integrates to one over the bins plus the out-of-range pseudo-bin.
  double integral = 0.0;
  for (std::size_t b = 0; b < model.counts().size(); ++b) {
    integral += std::exp(model.LogDensity(static_cast<float>((b + 0.5) * model.bin_width()))) * model.bin_width();
  }
  EXPECT_NEAR(integral, 1.0, 1e-3);
  EXPECT_GT(model.LogDensity(50.0f), model.LogDensity(20.0f));
  EXPECT_EQ(model.LogDensity(1e6f), model.LogDensity(2e6f));  // both beyond the last bin: pseudo-count only
  EXPECT_TRUE(std::isinf(model.LogDensity(std::numeric_limits<float>::infinity())));
}

TEST(HistogramSensorModelTest, RejectsUntrainableSamples) {
  CAIRN_EXPECT_THROWS_WITH(HistogramSensorModel::FromSamples({1.0f}), std::invalid_argument, "got 1 finite");
  CAIRN_EXPECT_THROWS_WITH(HistogramSensorModel::FromSamples({2.0f, 2.0f, 2.0f}), std::invalid_argument,
                           "all 3 cost samples equal");
  CAIRN_EXPECT_THROWS_WITH(HistogramSensorModel::FromSamples({1.0f, -2.0f}), std::invalid_argument, "negative");
  CAIRN_EXPECT_THROWS_WITH(HistogramSensorModel::FromSamples({1.0f, 2.0f}, 0.0), std::invalid_argument,
                           "pseudo_count");
}

}  // namespace
}  // namespace cairn::perception
