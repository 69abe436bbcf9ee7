#include "cairn/perception/synthetic/bars_scenario.h"

#include <cstdio>
#include <cstdlib>
#include <stdexcept>

#include "cairn/perception/evaluation/occupancy_score.h"
#include "cairn/perception/occupancy/cost_curve_sensor_model.h"
#include "cairn/perception/occupancy/wta_range_sensor_model.h"
#include "cairn/perception/stereo/compute_confidence.h"
#include "cairn/perception/stereo/compute_cost_volume.h"
#include "cairn/perception/stereo/cost_samples.h"
#include "cairn/perception/synthetic/synthetic_stereo_renderer.h"
#include "expect_throws.h"

namespace cairn::perception {
namespace {

struct BarsResult {
  OccupancyScore score;
  int bars_found{0};
  double min_bar_recall{1.0};
};

// Thesis Figs. 4.7/4.8: 20 frames around seven identical bars; the cost-curve grid (Merrell, ML parameters)
// against WTA grids filtered by peak ratio.
class BarsScenarioTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    scenario_ = new BarsScenario(BarsScenario::Make(20));
    SyntheticStereoRenderer renderer(scenario_->calibration, scenario_->width, scenario_->height, 0.0, 1);
    CostVolumeOptions options;
    options.cost = CostFunction::kBtSad;
    options.window = 9;
    options.min_disparity = scenario_->min_disparity;
    options.max_disparity = scenario_->max_disparity;
    const std::vector<double> ratios = {1.4, 1.5, 1.6};
    OccupancyGrid prototype(scenario_->grid_min_corner, scenario_->grid_resolution, scenario_->grid_dims);
    cost_curve_ = new OccupancyGrid(prototype);
    for (std::size_t i = 0; i < ratios.size(); ++i) wta_.push_back(new OccupancyGrid(prototype));
    for (std::size_t f = 0; f < scenario_->trajectory.size(); ++f) {
      const auto frame = renderer.Render(scenario_->scene, scenario_->trajectory[f], static_cast<int>(f));
      DisparityVolume costs;
      ComputeCostVolume(frame.left, frame.right, options, &costs);
      WtaResult wta;
      ComputeWinnerTakeAll(costs, WtaOptions{}, &wta);
      std::vector<float> samples;
      CollectConsistentWtaCosts(costs, wta, &samples);
      const auto model =
          ConfidenceModel::FitMaximumLikelihood(ConfidenceModelType::kMerrell, CostFunction::kBtSad, samples);
      DisparityVolume confidence;
      ComputeConfidence(costs, model, &confidence);
      CostCurveSensorModel().Integrate(confidence, scenario_->calibration, frame.X_WC, cost_curve_);
      for (std::size_t i = 0; i < ratios.size(); ++i) {
        WtaRangeSensorModel::Options wta_options;
        wta_options.min_peak_ratio = ratios[i];
        WtaRangeSensorModel(wta_options)
            .Integrate(wta, scenario_->min_disparity, scenario_->max_disparity, scenario_->calibration, frame.X_WC,
                       wta_[i]);
      }
    }
  }
  static void TearDownTestSuite() {
    delete scenario_;
    delete cost_curve_;
    for (auto* g : wta_) delete g;
    wta_.clear();
  }

  static BarsResult Score(const OccupancyGrid& grid) {
    BarsResult result;
    result.score = ScoreOccupancy(grid, RasterizeScene(scenario_->scene, grid));
    for (const auto& bar : scenario_->bars) {
      const auto s = ScoreOccupancy(grid, RasterizeScene(bar, grid));
      result.min_bar_recall = std::min(result.min_bar_recall, s.recall);
      if (s.recall >= 0.3) ++result.bars_found;
    }
    return result;
  }

  static BarsScenario* scenario_;
  static OccupancyGrid* cost_curve_;
  static std::vector<OccupancyGrid*> wta_;
};

BarsScenario* BarsScenarioTest::scenario_ = nullptr;
OccupancyGrid* BarsScenarioTest::cost_curve_ = nullptr;
std::vector<OccupancyGrid*> BarsScenarioTest::wta_;

TEST_F(BarsScenarioTest, CostCurveGridRecoversAllSevenBarsAndWtaDoesNot) {
  const BarsResult cc = Score(*cost_curve_);
  std::printf("cost-curve merrell-ML: precision %.3f recall %.3f (tp %zu fp %zu n %zu) bars %d min bar recall %.3f\n",
              cc.score.precision, cc.score.recall, cc.score.true_positives, cc.score.false_positives,
              cc.score.num_occupied, cc.bars_found, cc.min_bar_recall);
  if (std::getenv("CAIRN_BARS_ASCII") != nullptr) {
    for (const OccupancyGrid* g : {cost_curve_, wta_[0]}) {
      const auto truth = RasterizeScene(scenario_->scene, *g);
      for (int y = g->dims().y() - 1; y >= 0; --y) {
        for (int x = 0; x < g->dims().x(); ++x) {
          const std::size_t i = g->Index(Eigen::Vector3i(x, y, 6));
          const bool occ = g->probability(i) > 0.5;
          std::putchar(occ ? (truth[i] ? '#' : 'o') : (truth[i] ? '.' : (g->log_odds(i) == 0.0f ? ' ' : '-')));
        }
        std::putchar('\n');
      }
      std::putchar('\n');
    }
  }
  // Measured (noise-free, 20 frames, 640 x 480, 5 cm cells): cost-curve precision 0.978 (fp 7), recall 0.920,
  // all 7 bars (the misses are the bars' back rows, seen only obliquely); WTA precision 0.687 / 0.645 / 0.625 for
  // peak ratios 1.4 / 1.5 / 1.6 (fp 153 / 185 / 202: ghost bars and halos that a stricter filter leaves uncarved)
  // at recall 1.0.
  EXPECT_EQ(cc.bars_found, 7);
  EXPECT_GE(cc.score.precision, 0.9);
  EXPECT_GT(cc.score.recall, 0.85);
  const double ratios[3] = {1.4, 1.5, 1.6};
  for (int i = 0; i < 3; ++i) {
    const BarsResult w = Score(*wta_[i]);
    std::printf("WTA peak ratio %.1f:     precision %.3f recall %.3f (tp %zu fp %zu n %zu) bars %d min bar recall %.3f\n",
                ratios[i], w.score.precision, w.score.recall, w.score.true_positives, w.score.false_positives,
                w.score.num_occupied, w.bars_found, w.min_bar_recall);
    // The thesis' finding: no threshold gives a WTA grid without outliers and without holes.
    EXPECT_TRUE(w.score.false_positives > 10 * cc.score.false_positives || w.bars_found < 7)
        << "peak ratio " << ratios[i];
    EXPECT_GT(cc.score.precision, w.score.precision + 0.2) << "peak ratio " << ratios[i];
  }
}

}  // namespace
}  // namespace cairn::perception
