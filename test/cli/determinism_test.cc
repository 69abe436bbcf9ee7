// The same input gives the same bytes: `cairn plan` (plan.json, plan.png) and `cairn occupancy --ply` run twice,
// and the occupancy pipeline behind `cairn occupancy` with 1, 2 and 3 threads. (The command has no thread option:
// it uses every core, so the thread counts are varied through the library's own num_threads options.)

#include <unistd.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "../planning/support/shared_oracle.h"
#include "cairn/perception/occupancy/cost_curve_sensor_model.h"
#include "cairn/perception/occupancy/occupancy_grid.h"
#include "cairn/perception/synthetic/occupancy_scenario.h"
#include "cairn/perception/occupancy/wta_range_sensor_model.h"
#include "cairn/perception/stereo/compute_confidence.h"
#include "cairn/perception/stereo/compute_cost_volume.h"
#include "cairn/perception/stereo/confidence_model.h"
#include "cairn/perception/stereo/cost_samples.h"
#include "cairn/perception/synthetic/synthetic_stereo_renderer.h"
#include "cairn/perception/stereo/winner_take_all.h"
#include "run_cairn.h"
#include "test_paths.h"

namespace {

using cairn::test::CairnRun;
using cairn::test::RunCairn;
namespace fs = std::filesystem;

const std::string kScenarios = std::string(CAIRN_SOURCE_DIR) + "/examples/scenarios/";
const std::string kOracleCache = std::string(CAIRN_BINARY_DIR) + "/test-oracle-cache";

std::string ReadBytes(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

// `json` (a --json report on stdout) with the value of each wall-clock field `"<key>": <number>` replaced by "T". Counts the replacements in
// `found` so that a test sees when a key it masks is missing (and the masking would hide nothing).
std::string MaskWallTimes(const std::string& json, const std::vector<std::string>& keys, int* found) {
  std::string masked = json;
  *found = 0;
  for (const std::string& key : keys) {
    const std::string field = "\"" + key + "\": ";
    for (std::size_t at = masked.find(field); at != std::string::npos; at = masked.find(field, at)) {
      const std::size_t value = at + field.size();
      const std::size_t end = masked.find_first_not_of("-0123456789.eE+", value);
      if (end == value) {  // not a number (e.g. a key that ends the same way): leave it
        at = value;
        continue;
      }
      masked.replace(value, end - value, "T");
      ++*found;
      at = value;
    }
  }
  return masked;
}

class DeterminismTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("cairn_determinism_" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
};

TEST_F(DeterminismTest, PlanWritesTheSameJsonAndPictureOnEveryRun) {
  cairn::planning::test::SharedOracle(cairn::planning::WalkingObjective::kComWorkPlusHeat);
  // The shipped flat scenario with an expansion budget instead of its time limit: the search then stops at the
  // same point on any machine and under any load (the generous time limit is never reached). 60 expansions stop
  // it before it proves the optimum (it needs 91).
  std::istringstream shipped(ReadBytes(kScenarios + "flat.yaml"));
  std::ofstream scenario(dir_ / "flat.yaml");
  std::string line;
  int replaced = 0;
  while (std::getline(shipped, line)) {
    if (line.rfind("planner:", 0) == 0) {
      line = "planner: {time_limit: 600, max_expansions: 60}";
      ++replaced;
    }
    scenario << line << "\n";
  }
  scenario.close();
  ASSERT_EQ(replaced, 1) << "flat.yaml's one-line planner: entry changed; update this test";

  for (const char* run : {"a", "b"}) {
    const CairnRun result = RunCairn("plan --scenario " + (dir_ / "flat.yaml").string() + " --oracle-cache " +
                                     kOracleCache + " --out " + (dir_ / run).string());
    ASSERT_EQ(result.exit_code, 0) << result.output;
    ASSERT_THAT(result.output, ::testing::HasSubstr(" 60 expansions"));
  }
  const std::string png_a = ReadBytes(dir_ / "a" / "plan.png");
  ASSERT_GT(png_a.size(), 1000u);
  EXPECT_TRUE(png_a == ReadBytes(dir_ / "b" / "plan.png")) << "plan.png differs between two runs";
  // plan.json leaves out the wall-clock times the --json report has, so the whole file is byte-identical.
  const std::string json_a = ReadBytes(dir_ / "a" / "plan.json");
  const std::string json_b = ReadBytes(dir_ / "b" / "plan.json");
  EXPECT_THAT(json_a, ::testing::Not(::testing::HasSubstr("_ms\"")));
  EXPECT_THAT(json_a, ::testing::HasSubstr("\"found\": true"));
  EXPECT_EQ(json_a, json_b);
}

TEST_F(DeterminismTest, OccupancyWritesTheSamePlyAndScoresOnEveryRun) {
  const std::string scenario = kScenarios + "occupancy/boxes_on_floor.yaml";
  std::vector<std::string> outputs;
  for (const char* run : {"a.ply", "b.ply"}) {
    const CairnRun result = RunCairn("occupancy --scenario " + scenario + " --model merrell --frames 2 --json --ply " +
                                     (dir_ / run).string());
    ASSERT_EQ(result.exit_code, 0) << result.output;
    int found = 0;
    outputs.push_back(MaskWallTimes(result.output, {"ms", "ms_per_frame"}, &found));
    EXPECT_EQ(found, 3) << result.output;  // one per frame and the mean
  }
  EXPECT_EQ(outputs[0], outputs[1]);
  const std::string ply_a = ReadBytes(dir_ / "a.ply");
  EXPECT_THAT(ply_a, ::testing::StartsWith("ply\n"));
  EXPECT_THAT(ply_a, ::testing::Not(::testing::HasSubstr("element vertex 0\n")));
  EXPECT_TRUE(ply_a == ReadBytes(dir_ / "b.ply")) << "the PLY files of two runs differ";
}

// The grid after two frames of boxes_on_floor with every stage on `threads` threads, as `cairn occupancy` computes
// it (cost volume, winner-take-all, then the maximum-likelihood cost-curve model or the WTA range model).
cairn::perception::OccupancyGrid FuseBoxesOnFloor(bool wta_model, int threads) {
  using namespace cairn::perception;
  const OccupancyScenario scenario = OccupancyScenario::FromYaml(kScenarios + "occupancy/boxes_on_floor.yaml");
  const SyntheticStereoRenderer renderer(scenario.calibration, scenario.width, scenario.height,
                                         scenario.noise_variance, scenario.seed);
  CostVolumeOptions options;
  options.cost = CostFunction::kBtSad;
  options.window = 9;
  options.min_disparity = scenario.min_disparity;
  options.max_disparity = scenario.max_disparity;
  options.num_threads = threads;
  WtaOptions wta_options;
  wta_options.num_threads = threads;
  WtaRangeSensorModel::Options range_options;
  range_options.min_peak_ratio = 1.5;
  range_options.num_threads = threads;
  const WtaRangeSensorModel range_sensor(range_options);
  CostCurveSensorModel::Options curve_options;
  curve_options.num_threads = threads;
  const CostCurveSensorModel curve_sensor(curve_options);
  OccupancyGrid grid(scenario.grid_min_corner, scenario.grid_resolution, scenario.grid_dims);
  DisparityVolume costs;
  DisparityVolume confidence;
  WtaResult wta;
  for (int f = 0; f < 2; ++f) {
    const auto frame = renderer.Render(scenario.scene, scenario.trajectory[static_cast<std::size_t>(f)], f);
    ComputeCostVolume(frame.left, frame.right, options, &costs);
    ComputeWinnerTakeAll(costs, wta_options, &wta);
    if (wta_model) {
      range_sensor.Integrate(wta, scenario.min_disparity, scenario.max_disparity, scenario.calibration, frame.X_WC,
                             &grid);
    } else {
      std::vector<float> samples;
      CollectConsistentWtaCosts(costs, wta, &samples);
      const auto model = ConfidenceModel::FitMaximumLikelihood(ConfidenceModelType::kMerrell, options.cost, samples);
      ComputeConfidence(costs, model, &confidence, threads);
      curve_sensor.Integrate(confidence, scenario.calibration, frame.X_WC, &grid);
    }
  }
  return grid;
}

TEST_F(DeterminismTest, OccupancyGridAndPlyAreTheSameForAnyThreadCount) {
  for (const bool wta_model : {false, true}) {
    SCOPED_TRACE(wta_model ? "wta range model" : "merrell cost-curve model");
    const cairn::perception::OccupancyGrid reference = FuseBoxesOnFloor(wta_model, 1);
    const fs::path reference_ply = dir_ / "threads_1.ply";
    reference.WritePly(reference_ply.string());
    ASSERT_FALSE(reference.OccupiedCells().empty());
    for (const int threads : {2, 3}) {
      SCOPED_TRACE("threads " + std::to_string(threads));
      const cairn::perception::OccupancyGrid grid = FuseBoxesOnFloor(wta_model, threads);
      ASSERT_EQ(grid.num_cells(), reference.num_cells());
      std::size_t differing = 0;
      for (std::size_t i = 0; i < grid.num_cells(); ++i) {
        const float a = grid.log_odds(i);
        const float b = reference.log_odds(i);
        if (std::memcmp(&a, &b, sizeof(float)) != 0) ++differing;
      }
      EXPECT_EQ(differing, 0u) << "cells whose log-odds differ from the single-threaded grid's, bit for bit";
      const fs::path ply = dir_ / ("threads_" + std::to_string(threads) + ".ply");
      grid.WritePly(ply.string());
      EXPECT_TRUE(ReadBytes(ply) == ReadBytes(reference_ply)) << "the PLY differs from the single-threaded one";
    }
  }
}

}  // namespace
