// Cairn's stereo and occupancy kernels against OpenCV's block matchers and OctoMap, in the same run.
// Pair: Middlebury venus resized to 640x480 (real texture); BTSAD 9x9, 64 disparities.

#include <cmath>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <benchmark/benchmark.h>
#include <octomap/octomap.h>
#include <opencv2/calib3d.hpp>
#include <opencv2/imgproc.hpp>

#include "cairn/perception/evaluation/middlebury_pair.h"
#include "cairn/perception/occupancy/cost_curve_sensor_model.h"
#include "cairn/perception/stereo/compute_confidence.h"
#include "cairn/perception/stereo/compute_cost_volume.h"
#include "cairn/perception/stereo/cost_samples.h"
#include "cairn/perception/stereo/winner_take_all.h"

namespace cairn::perception {
namespace {

struct Fixture {
  MiddleburyPair native;
  cv::Mat left, right;
  CostVolumeOptions options;
  DisparityVolume costs, confidence;
  WtaResult wta;
  std::optional<ConfidenceModel> model;
  StereoCalibration calibration{500.0, 500.0, 319.5, 239.5, 0.1};
  Fixture() {
    native = MiddleburyPair::Load(std::string(CAIRN_SHARED_DIR) + "/data/middlebury/venus", 8.0);
    cv::resize(native.left, left, cv::Size(640, 480));
    cv::resize(native.right, right, cv::Size(640, 480));
    options.cost = CostFunction::kBtSad;
    options.window = 9;
    options.min_disparity = 1;
    options.max_disparity = 64;
    ComputeCostVolume(left, right, options, &costs);
    ComputeWinnerTakeAll(costs, WtaOptions{}, &wta);
    std::vector<float> samples;
    CollectConsistentWtaCosts(costs, wta, &samples);
    model = ConfidenceModel::FitMaximumLikelihood(ConfidenceModelType::kMerrell, CostFunction::kBtSad, samples);
    ComputeConfidence(costs, *model, &confidence);
  }
};

Fixture& Data() {
  static Fixture fixture;
  return fixture;
}

// Bad-pixel rate (> 1 px, 10 px border, known and non-occluded ground truth) of a CV_32F disparity of `pair`.
double BadRate(const cv::Mat& disparity, const MiddleburyPair& pair) {
  std::size_t n = 0, bad = 0;
  for (int y = 10; y < disparity.rows - 10; ++y)
    for (int x = 10; x < disparity.cols - 10; ++x) {
      const float gt = pair.gt_left.at<float>(y, x);
      if (!(gt > 0.0f) || (!pair.occluded.empty() && pair.occluded.at<uint8_t>(y, x) != 0)) continue;
      ++n;
      const float d = disparity.at<float>(y, x);
      if (!(std::isfinite(d) && d >= 0.0f) || std::abs(d - gt) > 1.0f) ++bad;
    }
  return static_cast<double>(bad) / static_cast<double>(n);
}

// The Middlebury pairs at native size, with their ground-truth scales (data/middlebury/README.md).
const std::vector<std::pair<std::string, MiddleburyPair>>& NativePairs() {
  static const std::vector<std::pair<std::string, MiddleburyPair>> pairs = [] {
    std::vector<std::pair<std::string, MiddleburyPair>> loaded;
    for (const char* name : {"tsukuba", "venus", "sawtooth", "barn2", "bull", "poster"}) {
      const double scale = std::string(name) == "tsukuba" ? 16.0 : 8.0;
      loaded.emplace_back(name, MiddleburyPair::Load(std::string(CAIRN_SHARED_DIR) + "/data/middlebury/" + name,
                                                     scale));
    }
    return loaded;
  }();
  return pairs;
}

// Counter "<pair>_bad" for every pair: the bad-pixel rate of disparity_of(pair) (CV_32F, disparities 0..31).
template <typename DisparityOf>
void ReportBadPixelRates(benchmark::State& state, DisparityOf&& disparity_of) {
  for (const auto& [name, pair] : NativePairs()) state.counters[name + "_bad"] = BadRate(disparity_of(pair), pair);
}

// OpenCV's fixed-point disparities (16 per pixel) as CV_32F.
cv::Mat FromFixedPoint(const cv::Mat& disparity) {
  cv::Mat d32;
  disparity.convertTo(d32, CV_32F, 1.0 / 16.0);
  return d32;
}

// Cost volume and WTA in one pass (each row's winners while the row is in cache); the full volume is still
// written, as the confidence and occupancy stages need it.
void BM_CairnCostVolumeWta(benchmark::State& state) {
  Fixture& f = Data();
  DisparityVolume costs;
  WtaResult wta;
  for (auto _ : state) {
    ComputeCostVolumeAndWinnerTakeAll(f.left, f.right, f.options, WtaOptions{}, &costs, &wta);
    benchmark::DoNotOptimize(wta.disparity.data);
  }
  CostVolumeOptions native = f.options;
  native.min_disparity = 0;
  native.max_disparity = 31;
  ReportBadPixelRates(state, [&](const MiddleburyPair& pair) {
    ComputeCostVolumeAndWinnerTakeAll(pair.left, pair.right, native, WtaOptions{}, &costs, &wta);
    return wta.disparity.clone();
  });
}
BENCHMARK(BM_CairnCostVolumeWta)->Unit(benchmark::kMillisecond)->UseRealTime();

// The same as two calls: the WTA reads the whole volume back from memory.
void BM_CairnCostVolumeThenWta(benchmark::State& state) {
  Fixture& f = Data();
  DisparityVolume costs;
  WtaResult wta;
  for (auto _ : state) {
    ComputeCostVolume(f.left, f.right, f.options, &costs);
    ComputeWinnerTakeAll(costs, WtaOptions{}, &wta);
    benchmark::DoNotOptimize(wta.disparity.data);
  }
}
BENCHMARK(BM_CairnCostVolumeThenWta)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_CairnCostVolumeOnly(benchmark::State& state) {
  Fixture& f = Data();
  DisparityVolume costs;
  for (auto _ : state) {
    ComputeCostVolume(f.left, f.right, f.options, &costs);
    benchmark::DoNotOptimize(costs.data().data());
  }
}
BENCHMARK(BM_CairnCostVolumeOnly)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_OpenCvStereoBM(benchmark::State& state) {
  Fixture& f = Data();
  auto bm = cv::StereoBM::create(64, 9);
  cv::Mat disparity;
  for (auto _ : state) {
    bm->compute(f.left, f.right, disparity);
    benchmark::DoNotOptimize(disparity.data);
  }
  bm->setNumDisparities(32);
  ReportBadPixelRates(state, [&](const MiddleburyPair& pair) {
    bm->compute(pair.left, pair.right, disparity);
    return FromFixedPoint(disparity);
  });
}
BENCHMARK(BM_OpenCvStereoBM)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_OpenCvStereoSGBM(benchmark::State& state) {
  Fixture& f = Data();
  auto sgbm = cv::StereoSGBM::create(0, 64, 9, 8 * 81, 32 * 81);
  cv::Mat disparity;
  for (auto _ : state) {
    sgbm->compute(f.left, f.right, disparity);
    benchmark::DoNotOptimize(disparity.data);
  }
  sgbm->setNumDisparities(32);
  ReportBadPixelRates(state, [&](const MiddleburyPair& pair) {
    sgbm->compute(pair.left, pair.right, disparity);
    return FromFixedPoint(disparity);
  });
}
BENCHMARK(BM_OpenCvStereoSGBM)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_CairnConfidenceMerrell(benchmark::State& state) {
  Fixture& f = Data();
  DisparityVolume confidence;
  for (auto _ : state) {
    ComputeConfidence(f.costs, *f.model, &confidence);
    benchmark::DoNotOptimize(confidence.data().data());
  }
}
BENCHMARK(BM_CairnConfidenceMerrell)->Unit(benchmark::kMillisecond)->UseRealTime();

// 640x480 rays x 64 disparities into 5 cm voxels over 6.4 x 3.2 x 9.6 m in front of the camera.
void BM_CairnCostCurveOccupancyUpdate(benchmark::State& state) {
  Fixture& f = Data();
  OccupancyGrid grid(Eigen::Vector3d(-3.2, -1.6, 0.0), 0.05, Eigen::Vector3i(128, 64, 192));
  CostCurveSensorModel::Options options;
  options.num_threads = static_cast<int>(state.range(0));
  const CostCurveSensorModel sensor(options);
  // One frame before timing: the update keeps its per-thread accumulators between frames (8 bytes per cell and
  // thread, allocated by the first frame), so the loop measures the steady state of a stream of frames.
  sensor.Integrate(f.confidence, f.calibration, Eigen::Isometry3d::Identity(), &grid);
  for (auto _ : state) {
    sensor.Integrate(f.confidence, f.calibration, Eigen::Isometry3d::Identity(), &grid);
  }
  state.counters["fps"] = benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}
// Argument: threads. The CPU column is the calling thread's: with 2 threads, the time of half the rays plus half
// the merge, which is what a frame costs on 2 free cores.
BENCHMARK(BM_CairnCostCurveOccupancyUpdate)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_OctomapInsertWtaPoints(benchmark::State& state) {
  Fixture& f = Data();
  octomap::Pointcloud cloud;
  const double fb = f.calibration.depth_times_disparity();
  for (int y = 0; y < 480; ++y)
    for (int x = 0; x < 640; ++x) {
      const float d = f.wta.disparity.at<float>(y, x);
      if (!(d > 0.5f)) continue;
      const double z = fb / d;
      cloud.push_back(static_cast<float>((x - f.calibration.cx) / f.calibration.fx * z),
                      static_cast<float>((y - f.calibration.cy) / f.calibration.fy * z), static_cast<float>(z));
    }
  for (auto _ : state) {
    octomap::OcTree tree(0.05);
    tree.insertPointCloud(cloud, octomap::point3d(0.0f, 0.0f, 0.0f), 10.0);
    benchmark::DoNotOptimize(tree.size());
  }
  state.counters["points"] = static_cast<double>(cloud.size());
  state.counters["fps"] = benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_OctomapInsertWtaPoints)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
}  // namespace cairn::perception

BENCHMARK_MAIN();
