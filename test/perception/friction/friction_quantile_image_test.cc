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

// The largest |image − bisection| over all pixels, bisection run to 1e-7 on the exact (untabulated) CDFs.
double WorstErrorAgainstBisection(const MaterialRegistry& registry, const cv::Mat& probabilities, double eta,
                                  int threads) {
  const FrictionQuantileImage image(registry, {eta, QuantileMethod::kExact, 0.02, threads});
  const cv::Mat fast = image.Compute(probabilities);
  double worst = 0.0;
  for (int r = 0; r < probabilities.rows; ++r) {
    for (int c = 0; c < probabilities.cols; ++c) {
      Eigen::VectorXd p(registry.size());
      for (int i = 0; i < registry.size(); ++i) p[i] = probabilities.ptr<float>(r)[c * registry.size() + i];
      p /= p.sum();
      const double exact = FrictionQuantile(registry, p, eta, QuantileMethod::kExact, 1e-7);
      worst = std::max(worst, std::abs(exact - fast.at<float>(r, c)));
    }
  }
  return worst;
}

// Segmenter-like pixels (a dominant label, a softmax tail, as the benchmark's), one-hot pixels, and two-label
// mixtures of far-apart materials whose mixture CDF has a long flat stretch (Newton's guesses leave the bracket
// there, so the bisection safeguard is exercised).
cv::Mat HardProbabilities(const MaterialRegistry& registry, int rows, int cols, unsigned seed) {
  const int n = registry.size();
  cv::Mat image(rows, cols, CV_32FC(n));
  std::mt19937 random(seed);
  std::uniform_int_distribution<int> label(0, n - 1);
  std::exponential_distribution<double> tail(8.0);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int r = 0; r < rows; ++r) {
    for (int c = 0; c < cols; ++c) {
      std::vector<double> p(n, 0.0);
      const int kind = (r * cols + c) % 3;
      if (kind == 0) {
        for (int i = 0; i < n; ++i) p[i] = 0.01 * tail(random);
        p[label(random)] += 1.0;
      } else if (kind == 1) {
        p[label(random)] = 1.0;
      } else {
        const double w = 0.2 * unit(random);  // Light mass on a low-friction label, the rest on a high one.
        p[registry.IndexOf("grass")] = w;
        p[registry.IndexOf(unit(random) < 0.5 ? "ceramic" : "carpet")] = 1.0 - w;
      }
      double sum = 0.0;
      for (double v : p) sum += v;
      for (int i = 0; i < n; ++i) image.ptr<float>(r)[c * n + i] = static_cast<float>(p[i] / sum);
    }
  }
  return image;
}

TEST(FrictionQuantileImageTest, SegmenterLikeAndBimodalPixelsMatchBisectionWithin1e4) {
  const auto registry = MaterialRegistry::ThesisTable33();
  const cv::Mat probabilities = HardProbabilities(registry, 24, 40, 17);
  for (const double eta : {0.95, 0.8, 0.99}) {
    EXPECT_LT(WorstErrorAgainstBisection(registry, probabilities, eta, 2), 1e-4) << "eta " << eta;
  }
}

TEST(FrictionQuantileImageTest, OtherDistributionKindsMatchBisectionWithin1e4) {
  // Truncated normals and GEVs (with both shape signs) next to a normal and a not-walkable label.
  const MaterialRegistry registry({{"ice", FrictionDistribution::GeneralizedExtremeValue(0.15, 0.04, -0.1)},
                                   {"rubber", FrictionDistribution::GeneralizedExtremeValue(0.9, 0.1, 0.2)},
                                   {"mud", FrictionDistribution::TruncatedNormal(0.2, 0.15)},
                                   {"asphalt", FrictionDistribution::Normal(0.74, 0.12)},
                                   {"water", FrictionDistribution::NotWalkable()}});
  EXPECT_LT(WorstErrorAgainstBisection(registry, RandomProbabilities(registry, 20, 20, 23), 0.95, 1), 1e-4);
}

TEST(FrictionQuantileImageTest, MixtureQuantileLiesBetweenTheComponentQuantiles) {
  // The bound the table's range rests on: for weights p_i > 0, min_i q_i <= Q <= max_i q_i, where q_i is label
  // i's own quantile (clipped at 0 like Q): below every q_i each F_i is under the target, so their mixture is
  // too; at the largest q_i every F_i has reached it.
  const auto registry = MaterialRegistry::ThesisTable33();
  const cv::Mat probabilities = HardProbabilities(registry, 10, 30, 29);
  const double eta = 0.95;
  for (int k = 0; k < probabilities.rows * probabilities.cols; ++k) {
    Eigen::VectorXd p(registry.size());
    double low = 1e9, high = 0.0;
    for (int i = 0; i < registry.size(); ++i) {
      p[i] = probabilities.ptr<float>(0)[k * registry.size() + i];
      if (p[i] <= 0.0) continue;
      const double q = std::max(0.0, registry.material(i).friction.Quantile(1.0 - eta));
      low = std::min(low, q);
      high = std::max(high, q);
    }
    p /= p.sum();
    const double quantile = FrictionQuantile(registry, p, eta, QuantileMethod::kExact, 1e-9);
    EXPECT_GE(quantile, low - 1e-8) << "pixel " << k;
    EXPECT_LE(quantile, high + 1e-8) << "pixel " << k;
  }
}

TEST(FrictionQuantileImageTest, SearchAndGaussianMatchThePerPixelFunctions) {
  const auto registry = MaterialRegistry::ThesisTable33();
  const cv::Mat probabilities = RandomProbabilities(registry, 8, 8, 5);
  const cv::Mat searched =
      FrictionQuantileImage(registry, {0.9, QuantileMethod::kSearch, 0.02, 1}).Compute(probabilities);
  const cv::Mat gaussian =
      FrictionQuantileImage(registry, {0.9, QuantileMethod::kGaussian, 0.02, 1}).Compute(probabilities);
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
  for (const cv::Mat& probabilities :
       {RandomProbabilities(registry, 31, 17, 9), HardProbabilities(registry, 31, 17, 9)}) {
    for (const QuantileMethod method :
         {QuantileMethod::kExact, QuantileMethod::kSearch, QuantileMethod::kGaussian}) {
      const cv::Mat one = FrictionQuantileImage(registry, {0.95, method, 0.02, 1}).Compute(probabilities);
      const cv::Mat three = FrictionQuantileImage(registry, {0.95, method, 0.02, 3}).Compute(probabilities);
      EXPECT_EQ(cv::norm(one, three, cv::NORM_INF), 0.0);
    }
  }
}

TEST(FrictionQuantileImageTest, RejectsBadImagesAndOptions) {
  const auto registry = MaterialRegistry::ThesisTable33();
  const FrictionQuantileImage image(registry, {});
  CAIRN_EXPECT_THROWS_WITH(image.Compute(cv::Mat(4, 4, CV_32FC3)), std::invalid_argument, "CV_32FC(14)",
                           "3 channel(s)");
  cv::Mat bad(2, 2, CV_32FC(14), cv::Scalar::all(0.0));
  CAIRN_EXPECT_THROWS_WITH(image.Compute(bad), std::invalid_argument, "pixel (0, 0) sum to 0", "normalise");
  // The first bad pixel is named, whatever the row's position in a thread's band.
  cv::Mat later = RandomProbabilities(registry, 5, 7, 31);
  later.ptr<float>(3)[4 * 14 + 2] += 0.5f;
  CAIRN_EXPECT_THROWS_WITH(image.Compute(later), std::invalid_argument, "pixel (3, 4) sum to 1.5");
  later = RandomProbabilities(registry, 5, 7, 31);
  later.ptr<float>(2)[6 * 14 + 0] = -0.25f;
  later.ptr<float>(2)[6 * 14 + 1] += 0.25f;
  CAIRN_EXPECT_THROWS_WITH(image.Compute(later), std::invalid_argument, "pixel (2, 6) leave [0, 1]");
  later = RandomProbabilities(registry, 5, 7, 31);
  later.ptr<float>(4)[0] = std::nanf("");
  CAIRN_EXPECT_THROWS_WITH(image.Compute(later), std::invalid_argument, "pixel (4, 0) leave [0, 1]");
  CAIRN_EXPECT_THROWS_WITH(FrictionQuantileImage(registry, {1.5, QuantileMethod::kExact, 0.02, 1}),
                           std::invalid_argument, "eta", "got 1.5");
  CAIRN_EXPECT_THROWS_WITH(FrictionQuantileImage(registry, {0.9, QuantileMethod::kSearch, 0.0, 1}),
                           std::invalid_argument, "step must be finite and > 0");
}

}  // namespace
}  // namespace cairn::perception
