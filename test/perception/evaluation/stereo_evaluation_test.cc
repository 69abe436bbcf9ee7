#include "cairn/perception/evaluation/stereo_evaluation.h"

#include <cmath>
#include <cstdio>
#include <limits>
#include <random>
#include <stdexcept>

#include "cairn/perception/evaluation/middlebury_pair.h"
#include "cairn/perception/stereo/compute_confidence.h"
#include "cairn/perception/stereo/compute_cost_volume.h"
#include "cairn/perception/stereo/cost_samples.h"
#include "expect_throws.h"
#include "test_paths.h"

namespace cairn::perception {
namespace {

TEST(StereoEvaluationTest, RocAucOfPerfectAndRandomRankings) {
  const int n = 20000;
  std::vector<float> confidence(n);
  std::vector<uint8_t> error(n);
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
  for (int i = 0; i < n; ++i) {
    error[i] = i % 5 == 0 ? 1 : 0;  // 20 % errors
    confidence[i] = error[i] != 0 ? uniform(rng) * 0.5f : 0.5f + uniform(rng) * 0.5f;
  }
  EXPECT_NEAR(RocAuc(confidence, error), OptimalAuc(0.2), 1e-3);
  for (float& c : confidence) c = uniform(rng);
  EXPECT_NEAR(RocAuc(confidence, error), 0.2, 0.01);  // a random ranking sits at the error rate
  std::fill(confidence.begin(), confidence.end(), 1.0f);  // all tied: one group, the error rate
  EXPECT_NEAR(RocAuc(confidence, error), 0.2, 1e-9);
  EXPECT_NEAR(OptimalAuc(0.2), 0.2 + 0.8 * std::log(0.8), 1e-12);
  CAIRN_EXPECT_THROWS_WITH(RocAuc({1.0f}, {}), std::invalid_argument, "1 confidences and 0 error flags");
  CAIRN_EXPECT_THROWS_WITH(RocAuc({1.0f, std::nanf("")}, {0, 1}), std::invalid_argument, "confidence 1 is NaN");
  CAIRN_EXPECT_THROWS_WITH(OptimalAuc(1.5), std::invalid_argument, "1.5");
}

struct PairData {
  std::string name;
  double scale;
};

struct Evaluated {
  DisparityVolume costs;
  WtaResult wta;
  MiddleburyPair pair;
};

Evaluated Match(const PairData& data, CostFunction cost) {
  Evaluated e;
  e.pair = MiddleburyPair::Load(std::string(CAIRN_SHARED_DIR) + "/data/middlebury/" + data.name, data.scale);
  CostVolumeOptions options;
  options.cost = cost;
  options.window = 9;
  options.max_disparity = 31;
  ComputeCostVolume(e.pair.left, e.pair.right, options, &e.costs);
  ComputeWinnerTakeAll(e.costs, WtaOptions{}, &e.wta);
  return e;
}

StereoEvaluation Evaluate(const Evaluated& e, const ConfidenceModel& model) {
  DisparityVolume confidence;
  ComputeConfidence(e.costs, model, &confidence);
  return EvaluateStereo(confidence, e.wta, e.pair.gt_left, e.pair.occluded);
}

// Thesis section 4.3.4 on the Middlebury 2001 pairs: ML parameters without ground truth land close to the best
// fixed parameter, and an under-estimated parameter falls off the "performance cliff".
TEST(StereoEvaluationTest, MaximumLikelihoodMerrellIsNearTheBestParameterOnVenus) {
  const Evaluated e = Match({"venus", 8.0}, CostFunction::kBtSad);
  std::vector<float> samples;
  CollectConsistentWtaCosts(e.costs, e.wta, &samples);
  const auto ml = ConfidenceModel::FitMaximumLikelihood(ConfidenceModelType::kMerrell, CostFunction::kBtSad, samples);
  const StereoEvaluation at_ml = Evaluate(e, ml);
  EXPECT_LT(at_ml.bad_pixel_rate, 0.10);
  EXPECT_GT(at_ml.auc, at_ml.auc_optimal);
  EXPECT_LT(at_ml.auc, 0.6 * at_ml.bad_pixel_rate);  // much better than a random ranking
  double best_auc = 1.0;
  double best_c = 0.0;
  for (double factor : {1e-6, 0.01, 0.1, 0.3, 1.0, 3.0, 10.0, 100.0}) {
    const auto model = ConfidenceModel::Merrell(CostFunction::kBtSad, ml.parameter() * factor);
    const StereoEvaluation r = Evaluate(e, model);
    std::printf("venus merrell x%-6g auc %.4f c_gt_badpx %.4f\n", factor, r.auc, r.c_gt_badpx);
    if (factor == 1e-6) {
      EXPECT_GT(r.auc, 1.2 * at_ml.auc);
    }
    best_auc = std::min(best_auc, r.auc);
    best_c = std::max(best_c, r.c_gt_badpx);
    if (factor == 1e-6) {
      EXPECT_LT(r.c_gt_badpx, 0.5 * at_ml.c_gt_badpx);  // the cliff
    }
  }
  // Measured: 9.5 % from the sweep's best AUC, 24 % from its best C (thesis Table 4.2, Merrell BTSAD:
  // 0.13 +- 0.27 and 0.10 +- 0.08 on the 2003/2006 pairs).
  EXPECT_LT((at_ml.auc - best_auc) / best_auc, 0.2);
  EXPECT_LT((best_c - at_ml.c_gt_badpx) / best_c, 0.3);
}

// Across the five pairs with both ground truths: every model with ML parameters ranks far better than chance,
// and the HSM trained on the other pairs' true-disparity costs (the thesis' AGT HSM) has the lowest mean AUC.
TEST(StereoEvaluationTest, ModelsOnTheMiddleburyPairs) {
  const std::vector<PairData> pairs = {{"venus", 8.0}, {"sawtooth", 8.0}, {"barn2", 8.0}, {"bull", 8.0}, {"poster", 8.0}};
  std::vector<Evaluated> matched;
  std::vector<std::vector<float>> gt_samples(pairs.size());
  for (std::size_t i = 0; i < pairs.size(); ++i) {
    matched.push_back(Match(pairs[i], CostFunction::kBtSad));
    cv::Mat visible;
    cv::compare(matched.back().pair.occluded, 0, visible, cv::CMP_EQ);
    CollectGroundTruthCosts(matched.back().costs, matched.back().pair.gt_left, visible, &gt_samples[i]);
  }
  double auc_ml_merrell = 0.0, auc_ml_exp = 0.0, auc_agt_hsm = 0.0, optimal = 0.0, bad = 0.0;
  double c_ml_merrell = 0.0, c_ml_exp = 0.0;
  for (std::size_t i = 0; i < pairs.size(); ++i) {
    std::vector<float> samples;
    CollectConsistentWtaCosts(matched[i].costs, matched[i].wta, &samples);
    std::vector<float> others;
    for (std::size_t j = 0; j < pairs.size(); ++j)
      if (j != i) others.insert(others.end(), gt_samples[j].begin(), gt_samples[j].end());
    const auto merrell = Evaluate(matched[i], ConfidenceModel::FitMaximumLikelihood(ConfidenceModelType::kMerrell,
                                                                                   CostFunction::kBtSad, samples));
    const auto exponential = Evaluate(matched[i], ConfidenceModel::FitMaximumLikelihood(
                                                      ConfidenceModelType::kExponential, CostFunction::kBtSad, samples));
    const auto hsm = Evaluate(matched[i],
                              ConfidenceModel::Histogram(CostFunction::kBtSad, HistogramSensorModel::FromSamples(others)));
    std::printf("%-9s bad %.4f optimal %.4f | auc merrell %.4f exp %.4f agt-hsm %.4f | C merrell %.4f exp %.4f "
                "agt-hsm %.4f\n",
                pairs[i].name.c_str(), merrell.bad_pixel_rate, merrell.auc_optimal, merrell.auc, exponential.auc,
                hsm.auc, merrell.c_gt_badpx, exponential.c_gt_badpx, hsm.c_gt_badpx);
    for (const auto* r : {&merrell, &exponential, &hsm}) {
      EXPECT_LT(r->auc, r->bad_pixel_rate) << pairs[i].name;
      EXPECT_GT(r->auc, r->auc_optimal) << pairs[i].name;
      EXPECT_GT(r->c_gt_badpx, 0.0) << pairs[i].name;
      EXPECT_LT(r->c_gt_badpx, 1.0) << pairs[i].name;
    }
    auc_ml_merrell += merrell.auc;
    auc_ml_exp += exponential.auc;
    auc_agt_hsm += hsm.auc;
    c_ml_merrell += merrell.c_gt_badpx;
    c_ml_exp += exponential.c_gt_badpx;
    optimal += merrell.auc_optimal;
    bad += merrell.bad_pixel_rate;
  }
  const double n = static_cast<double>(pairs.size());
  std::printf("mean      bad %.4f optimal %.4f | auc merrell %.4f exp %.4f agt-hsm %.4f | C merrell %.4f exp %.4f\n",
              bad / n, optimal / n, auc_ml_merrell / n, auc_ml_exp / n, auc_agt_hsm / n, c_ml_merrell / n,
              c_ml_exp / n);
  EXPECT_LT(auc_agt_hsm, auc_ml_merrell);
  EXPECT_LT(auc_agt_hsm, auc_ml_exp);
}

TEST(StereoEvaluationTest, RejectsMismatchedGroundTruth) {
  DisparityVolume confidence(4, 4, 0, 1);
  WtaResult wta;
  wta.disparity = cv::Mat(4, 4, CV_32F, cv::Scalar(0.0f));
  CAIRN_EXPECT_THROWS_WITH(EvaluateStereo(confidence, wta, cv::Mat(5, 4, CV_32F), cv::Mat()), std::invalid_argument,
                           "4x5", "CV_32FC1");
}

// A small consistent volume, WTA and ground truth for the option checks: 12x10 pixels, disparities 0..3.
struct Tiny {
  DisparityVolume confidence{10, 12, 0, 3};
  WtaResult wta;
  cv::Mat gt{10, 12, CV_32F, cv::Scalar(2.0f)};
  Tiny() {
    DisparityVolume costs(10, 12, 0, 3);
    for (int y = 0; y < 10; ++y) {
      for (int x = 0; x < 12; ++x) {
        for (int k = 0; k < 4; ++k) costs.mutable_curve(y, x)[k] = k == 2 ? 0.0f : 5.0f;
      }
    }
    ComputeWinnerTakeAll(costs, WtaOptions{}, &wta);
    ComputeConfidence(costs, ConfidenceModel::Merrell(CostFunction::kBtSad, 4.0), &confidence);
  }
};

TEST(StereoEvaluationTest, RefusesBordersThatAreNegativeOrLeaveNoPixel) {
  const Tiny t;
  StereoEvaluationOptions options;
  options.border = 4;
  EXPECT_EQ(EvaluateStereo(t.confidence, t.wta, t.gt, cv::Mat(), options).num_pixels, 2u * 4u);
  options.border = -1;  // used to read row -1 (a segfault)
  CAIRN_EXPECT_THROWS_WITH(EvaluateStereo(t.confidence, t.wta, t.gt, cv::Mat(), options), std::invalid_argument,
                           "border -1 is negative");
  options.border = 5;
  CAIRN_EXPECT_THROWS_WITH(EvaluateStereo(t.confidence, t.wta, t.gt, cv::Mat(), options), std::invalid_argument,
                           "border 5 leaves no pixel of the 12x10 image", "at most 4");
  options.border = 0;
  options.bad_threshold = std::nan("");
  CAIRN_EXPECT_THROWS_WITH(EvaluateStereo(t.confidence, t.wta, t.gt, cv::Mat(), options), std::invalid_argument,
                           "bad_threshold nan");
  options.bad_threshold = 1.0;
  options.gt_interval = -1.0;
  CAIRN_EXPECT_THROWS_WITH(EvaluateStereo(t.confidence, t.wta, t.gt, cv::Mat(), options), std::invalid_argument,
                           "gt_interval -1");
  options.gt_interval = 1e300;  // clamped to the volume's range, never converted out of range
  EXPECT_NO_THROW(EvaluateStereo(t.confidence, t.wta, t.gt, cv::Mat(), options));
}

TEST(StereoEvaluationTest, RefusesAWinnerTakeAllResultFromAnotherVolume) {
  Tiny t;
  StereoEvaluationOptions options;
  options.border = 0;
  t.wta.best_index.at<int32_t>(3, 5) = 4;  // the volume has 4 disparities
  CAIRN_EXPECT_THROWS_WITH(EvaluateStereo(t.confidence, t.wta, t.gt, cv::Mat(), options), std::invalid_argument,
                           "index 4 at pixel (5, 3)", "4 disparities");
  t.wta.best_index = cv::Mat();
  CAIRN_EXPECT_THROWS_WITH(EvaluateStereo(t.confidence, t.wta, t.gt, cv::Mat()), std::invalid_argument,
                           "does not match");
  CAIRN_EXPECT_THROWS_WITH(EvaluateStereo(DisparityVolume(), t.wta, t.gt, cv::Mat()), std::invalid_argument,
                           "confidence volume is empty");
}

TEST(StereoEvaluationTest, AutomaticMaxDisparityRoundsTheGroundTruthUpAndRefusesNonsense) {
  cv::Mat gt(4, 64, CV_32F, cv::Scalar(0.0f));
  gt.at<float>(1, 1) = 19.75f;
  EXPECT_EQ(AutomaticMaxDisparity(gt), 31);
  gt.at<float>(2, 2) = 32.0f;
  EXPECT_EQ(AutomaticMaxDisparity(gt), 47);
  gt.at<float>(2, 2) = 60.0f;
  EXPECT_EQ(AutomaticMaxDisparity(gt), 63);  // never past the image
  gt.at<float>(2, 2) = 64.0f;
  CAIRN_EXPECT_THROWS_WITH(AutomaticMaxDisparity(gt), std::invalid_argument, "largest disparity 64",
                           "width 64", "scale");
  CAIRN_EXPECT_THROWS_WITH(AutomaticMaxDisparity(cv::Mat(4, 4, CV_32F, cv::Scalar(0.0f))), std::invalid_argument,
                           "no known");
  gt.at<float>(2, 2) = std::numeric_limits<float>::infinity();
  CAIRN_EXPECT_THROWS_WITH(AutomaticMaxDisparity(gt), std::invalid_argument, "non-finite");
  CAIRN_EXPECT_THROWS_WITH(AutomaticMaxDisparity(cv::Mat(2, 2, CV_8U)), std::invalid_argument, "CV_32FC1");
}

}  // namespace
}  // namespace cairn::perception
