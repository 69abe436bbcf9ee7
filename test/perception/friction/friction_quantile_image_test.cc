#include "cairn/perception/friction/friction_quantile_image.h"

#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "expect_throws.h"

namespace cairn::perception {
namespace {

// Random per-pixel mixtures: mostly one dominant label (as a segmenter gives), some mixed, some not walkable.
cv::Mat RandomProbabilities(const MaterialRegistry& registry, int rows, int cols, unsigned seed) {
  const int n = registry.size();
  cv::Mat image(rows, cols, CV_32FC(n));
  std::mt19937 random(seed);
  std::gamma_distribution<double> gamma(0.2, 1.0);
  for (int r = 0; r < rows; ++r) {
    float* row = image.ptr<float>(r);
    for (int c = 0; c < cols; ++c) {
      double sum = 0.0;
      std::vector<double> p(n);
      for (int i = 0; i < n; ++i) sum += (p[i] = gamma(random) + 1e-12);
      for (int i = 0; i < n; ++i) row[c * n + i] = static_cast<float>(p[i] / sum);
    }
  }
  return image;
}

TEST(FrictionQuantileImageTest, TabulatedExactMatchesBisectionWithin1e4) {
  const auto registry = MaterialRegistry::ThesisTable33();
  const cv::Mat probabilities = RandomProbabilities(registry, 20, 30, 3);
  FrictionQuantileImage image(registry, {0.95, QuantileMethod::kExact, 0.02, 2});
  EXPECT_LT(image.cdf_interpolation_error(), 1e-4);
  const cv::Mat fast = image.Compute(probabilities);
  double worst = 0.0;
  for (int r = 0; r < probabilities.rows; ++r) {
    for (int c = 0; c < probabilities.cols; ++c) {
      Eigen::VectorXd p(registry.size());
      for (int i = 0; i < registry.size(); ++i) p[i] = probabilities.ptr<float>(r)[c * registry.size() + i];
      p /= p.sum();
      const double exact = FrictionQuantile(registry, p, 0.95, QuantileMethod::kExact, 1e-7);
      worst = std::max(worst, std::abs(exact - fast.at<float>(r, c)));
    }
  }
  EXPECT_LT(worst, 1e-4);
}

TEST(FrictionQuantileImageTest, SearchAndGaussianMatchThePerPixelFunctions) {
  const auto registry = MaterialRegistry::ThesisTable33();
  const cv::Mat probabilities = RandomProbabilities(registry, 8, 8, 5);
  const cv::Mat searched = FrictionQuantileImage(registry, {0.9, QuantileMethod::kSearch, 0.02, 1}).Compute(probabilities);
  const cv::Mat gaussian = FrictionQuantileImage(registry, {0.9, QuantileMethod::kGaussian, 0.02, 1}).Compute(probabilities);
  for (int r = 0; r < 8; ++r) {
    for (int c = 0; c < 8; ++c) {
      Eigen::VectorXd p(registry.size());
      for (int i = 0; i < registry.size(); ++i) p[i] = probabilities.ptr<float>(r)[c * registry.size() + i];
      p /= p.sum();
      // Grid points may differ by one step where float and double CDFs straddle the target.
      EXPECT_NEAR(searched.at<float>(r, c), FrictionQuantile(registry, p, 0.9, QuantileMethod::kSearch, 0.02), 0.0201);
      EXPECT_NEAR(gaussian.at<float>(r, c), FrictionQuantile(registry, p, 0.9, QuantileMethod::kGaussian), 1e-5);
    }
  }
}

TEST(FrictionQuantileImageTest, ResultsDoNotDependOnTheThreadCount) {
  const auto registry = MaterialRegistry::ThesisTable33();
  const cv::Mat probabilities = RandomProbabilities(registry, 31, 17, 9);
  const cv::Mat one = FrictionQuantileImage(registry, {0.95, QuantileMethod::kExact, 0.02, 1}).Compute(probabilities);
  const cv::Mat three = FrictionQuantileImage(registry, {0.95, QuantileMethod::kExact, 0.02, 3}).Compute(probabilities);
  EXPECT_EQ(cv::norm(one, three, cv::NORM_INF), 0.0);
}

TEST(FrictionQuantileImageTest, RejectsBadImagesAndOptions) {
  const auto registry = MaterialRegistry::ThesisTable33();
  const FrictionQuantileImage image(registry, {});
  CAIRN_EXPECT_THROWS_WITH(image.Compute(cv::Mat(4, 4, CV_32FC3)), std::invalid_argument, "CV_32FC(14)",
                           "3 channel(s)");
  cv::Mat bad(2, 2, CV_32FC(14), cv::Scalar::all(0.0));
  CAIRN_EXPECT_THROWS_WITH(image.Compute(bad), std::invalid_argument, "pixel (0, 0) sum to 0", "normalise");
  CAIRN_EXPECT_THROWS_WITH(FrictionQuantileImage(registry, {1.5, QuantileMethod::kExact, 0.02, 1}),
                           std::invalid_argument, "eta", "got 1.5");
  CAIRN_EXPECT_THROWS_WITH(FrictionQuantileImage(registry, {0.9, QuantileMethod::kSearch, 0.0, 1}),
                           std::invalid_argument, "step must be finite and > 0");
}

}  // namespace
}  // namespace cairn::perception
