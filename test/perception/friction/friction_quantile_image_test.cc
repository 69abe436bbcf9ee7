#include "cairn/perception/friction/friction_quantile_image.h"

#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "expect_throws.h"

namespace cairn::perception {

// Reaches the image's choice of kernels (a friend of FrictionQuantileImage).
class FrictionQuantileImageTester {
 public:
  static bool UsesAvx2(const FrictionQuantileImage& image) { return image.avx2_; }
  // A copy of `image` that computes with the portable kernels, whatever the processor.
  static FrictionQuantileImage Portable(const FrictionQuantileImage& image) {
    FrictionQuantileImage copy = image;
    copy.avx2_ = false;
    return copy;
  }
};

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

// Probability spread over every label (a flat Dirichlet): no dominant label, so the searches start far from the
// root and the bisection safeguard takes over more often than for segmenter-like pixels.
cv::Mat SpreadProbabilities(int n, int rows, int cols, unsigned seed) {
  cv::Mat image(rows, cols, CV_32FC(n));
  std::mt19937 random(seed);
  std::exponential_distribution<double> exponential(1.0);
  for (int r = 0; r < rows; ++r) {
    for (int c = 0; c < cols; ++c) {
      std::vector<double> p(n);
      double sum = 0.0;
      for (double& v : p) sum += (v = exponential(random));
      for (int i = 0; i < n; ++i) image.ptr<float>(r)[c * n + i] = static_cast<float>(p[i] / sum);
    }
  }
  return image;
}

// The thesis' table with six more labels (20: the dot products span three 8-label chunks and two table blocks).
MaterialRegistry TwentyLabels() {
  std::vector<MaterialRegistry::Material> materials = MaterialRegistry::ThesisTable33().materials();
  materials.push_back({"ice", FrictionDistribution::GeneralizedExtremeValue(0.15, 0.04, -0.1), 0});
  materials.push_back({"rubber", FrictionDistribution::GeneralizedExtremeValue(0.9, 0.1, 0.2), 0});
  materials.push_back({"mud", FrictionDistribution::TruncatedNormal(0.2, 0.15), 0});
  materials.push_back({"gravel", FrictionDistribution::Normal(0.6, 0.1), 0});
  materials.push_back({"tile", FrictionDistribution::Normal(0.5, 0.05), 0});
  materials.push_back({"lava", FrictionDistribution::NotWalkable(), 0});
  return MaterialRegistry(std::move(materials));
}

TEST(FrictionQuantileImageTest, TwentyLabelsMatchBisectionWithin1e4) {
  const MaterialRegistry registry = TwentyLabels();
  ASSERT_EQ(registry.size(), 20);
  EXPECT_LT(WorstErrorAgainstBisection(registry, SpreadProbabilities(20, 12, 15, 41), 0.95, 2), 1e-4);
  EXPECT_LT(WorstErrorAgainstBisection(registry, RandomProbabilities(registry, 12, 15, 43), 0.9, 1), 1e-4);
}

// The AVX2 kernels (used when the processor has AVX2) and the portable ones add in the same order, so every
// method gives the same bits with either, for one, two and three 8-label chunks per pixel, on segmenter-like,
// bimodal and spread-out pixels, and rows of a length that is not a multiple of the kernels' 4 or 8 pixels. (On
// a processor without AVX2 both sides run the portable kernels, and the test checks that they are repeatable.)
TEST(FrictionQuantileImageTest, PortableKernelsGiveTheSameBitsAsTheAvx2Ones) {
  const auto thesis = MaterialRegistry::ThesisTable33();
  const MaterialRegistry five({{"ice", FrictionDistribution::GeneralizedExtremeValue(0.15, 0.04, -0.1)},
                               {"rubber", FrictionDistribution::GeneralizedExtremeValue(0.9, 0.1, 0.2)},
                               {"mud", FrictionDistribution::TruncatedNormal(0.2, 0.15)},
                               {"asphalt", FrictionDistribution::Normal(0.74, 0.12)},
                               {"water", FrictionDistribution::NotWalkable()}});
  const MaterialRegistry twenty = TwentyLabels();
  int compared = 0;
  for (const MaterialRegistry* registry : {&five, &thesis, &twenty}) {
    const int n = registry->size();
    std::vector<cv::Mat> images = {SpreadProbabilities(n, 9, 37, 7), RandomProbabilities(*registry, 9, 37, 8)};
    if (n == 14) images.push_back(HardProbabilities(*registry, 9, 37, 9));
    for (const QuantileMethod method :
         {QuantileMethod::kExact, QuantileMethod::kSearch, QuantileMethod::kGaussian}) {
      const FrictionQuantileImage fast(*registry, {0.95, method, 0.02, 2});
      const FrictionQuantileImage portable = FrictionQuantileImageTester::Portable(fast);
      ASSERT_FALSE(FrictionQuantileImageTester::UsesAvx2(portable));
      for (const cv::Mat& probabilities : images) {
        const cv::Mat a = fast.Compute(probabilities);
        const cv::Mat b = portable.Compute(probabilities);
        ASSERT_EQ(a.size(), b.size());
        EXPECT_EQ(std::memcmp(a.data, b.data, a.total() * a.elemSize()), 0)
            << n << " labels, method " << static_cast<int>(method) << ", largest difference "
            << cv::norm(a, b, cv::NORM_INF);
        ++compared;
      }
    }
  }
  EXPECT_EQ(compared, 3 * 7);
  // Both name the same first bad pixel.
  cv::Mat bad = RandomProbabilities(thesis, 4, 9, 12);
  bad.ptr<float>(2)[8 * 14 + 13] += 0.01f;
  const FrictionQuantileImage fast(thesis, {0.95, QuantileMethod::kExact, 0.02, 1});
  for (const FrictionQuantileImage& image : {fast, FrictionQuantileImageTester::Portable(fast)}) {
    CAIRN_EXPECT_THROWS_WITH(image.Compute(bad), std::invalid_argument, "pixel (2, 8) sum to 1.01");
  }
}

// A region of a larger image: its rows are not contiguous, and past each row's last pixel lie other pixels, here
// NaN, which the kernels must not read.
TEST(FrictionQuantileImageTest, RegionOfALargerImageIsReadWithinItsRows) {
  const auto registry = MaterialRegistry::ThesisTable33();
  cv::Mat canvas(12, 20, CV_32FC(14));
  canvas.reshape(1).setTo(std::numeric_limits<double>::quiet_NaN());
  const cv::Mat region = canvas(cv::Rect(3, 2, 13, 9));
  HardProbabilities(registry, 9, 13, 21).copyTo(region);
  ASSERT_FALSE(region.isContinuous());
  for (const QuantileMethod method : {QuantileMethod::kExact, QuantileMethod::kSearch, QuantileMethod::kGaussian}) {
    const FrictionQuantileImage image(registry, {0.95, method, 0.02, 2});
    const cv::Mat expected = image.Compute(region.clone());
    for (const FrictionQuantileImage& kernels : {image, FrictionQuantileImageTester::Portable(image)}) {
      const cv::Mat quantiles = kernels.Compute(region);
      ASSERT_EQ(quantiles.size(), region.size());
      EXPECT_EQ(cv::norm(quantiles, expected, cv::NORM_INF), 0.0) << "method " << static_cast<int>(method);
    }
  }
}

TEST(FrictionQuantileImageTest, OutputMayBeTheInput) {
  // Compute(p, &p) replaces the probabilities by the quantiles; with one label the two even have the same type,
  // and the output must still not overwrite pixels before they are read.
  const auto registry = MaterialRegistry::ThesisTable33();
  const FrictionQuantileImage image(registry, {});
  cv::Mat probabilities = HardProbabilities(registry, 5, 6, 33);
  const cv::Mat expected = image.Compute(probabilities);
  image.Compute(probabilities, &probabilities);
  ASSERT_EQ(probabilities.type(), CV_32F);
  EXPECT_EQ(cv::norm(probabilities, expected, cv::NORM_INF), 0.0);

  const MaterialRegistry single({{"asphalt", FrictionDistribution::Normal(0.74, 0.12)}});
  const FrictionQuantileImage one_label(single, {});
  cv::Mat ones(3, 4, CV_32FC1, cv::Scalar(1.0));
  one_label.Compute(ones, &ones);
  const double expected_quantile = single.material(0).friction.Quantile(0.05);
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 4; ++c) EXPECT_NEAR(ones.at<float>(r, c), expected_quantile, 1e-4);
  }
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
  // A tiny step made the table's size overflow int (and ask for gigabytes).
  CAIRN_EXPECT_THROWS_WITH(FrictionQuantileImage(registry, {0.9, QuantileMethod::kSearch, 1e-12, 1}),
                           std::invalid_argument, "in steps of 1e-12", "more than the 1e+06 supported",
                           "raise the tolerance");
}

}  // namespace
}  // namespace cairn::perception
