#include "fuzz_harnesses.h"

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>

#include <Eigen/Core>
#include <opencv2/core.hpp>

#include "cairn/multibody/center_of_mass.h"
#include "cairn/multibody/configuration.h"
#include "cairn/multibody/data.h"
#include "cairn/multibody/kinematics.h"
#include "cairn/multibody/urdf_parser.h"
#include "cairn/perception/friction/builtin_material_segmenter.h"
#include "cairn/perception/friction/material_registry.h"
#include "cairn/perception/friction/onnx_material_segmenter.h"
#include "cairn/perception/synthetic/occupancy_scenario.h"
#include "cairn/perception/evaluation/middlebury_pair.h"
#include "cairn/planning/scenarios/footstep_scenario.h"
#include "cairn/planning/locomotion/transition_oracle.h"
#include "cairn/planning/locomotion/walking_model.h"
#include "cairn/planning/locomotion/walking_objective.h"
#include "fuzz_input_file.h"

namespace cairn::fuzz {
namespace {

const std::string kSource = CAIRN_SOURCE_DIR;

// The transition oracle harness's table: 8 entries inside the humanoid's reach, so that a seed is 1 kB and
// Build() takes seconds.
planning::OracleGrid FuzzOracleGrid() {
  planning::OracleGrid grid;
  grid.dx = {0.0, 0.1};
  grid.dy = {0.2, 0.25};
  grid.dz = {0.0};
  grid.dtheta = {0.0};
  grid.mu = {0.5, 1.0};
  return grid;
}

constexpr planning::WalkingObjective kOracleObjective = planning::WalkingObjective::kComWorkPlusHeat;

const planning::WalkingModel& HumanoidWalkingModel() {
  static const planning::WalkingModel model =
      planning::WalkingModel::Load(kSource + "/data/robots/cairn_humanoid_walking.yaml");
  return model;
}

// FNV-1a 64, the transition oracle file's payload checksum (docs in transition_oracle.h).
std::uint64_t Fnv1a(std::string_view bytes) {
  std::uint64_t hash = 1469598103934665603ULL;
  for (unsigned char c : bytes) {
    hash ^= c;
    hash *= 1099511628211ULL;
  }
  return hash;
}

// `file` with its "checksum <hex>" header line rewritten to the checksum of the bytes after the "end" line that
// follows it; unchanged when it has no such lines.
std::string WithPayloadChecksum(std::string file) {
  const std::size_t key = file.find("\nchecksum ");
  if (key == std::string::npos) return file;
  const std::size_t value = key + 10;
  const std::size_t line_end = file.find('\n', value);
  if (line_end == std::string::npos) return file;
  const std::size_t end_line = file.find("\nend\n", line_end - 1);
  if (end_line == std::string::npos) return file;
  char hex[24];
  std::snprintf(hex, sizeof(hex), "%016llx",
                static_cast<unsigned long long>(Fnv1a(std::string_view(file).substr(end_line + 5))));
  file.replace(value, line_end - value, hex);
  return file;
}

}  // namespace

void FuzzUrdf(std::string_view input) {
  const std::string xml(input);
  for (const bool floating : {false, true}) {
    multibody::UrdfOptions options;
    options.floating_base = floating;
    const multibody::Model model = multibody::ParseUrdfString(xml, kSource + "/data/robots", options, "<fuzz>");
    multibody::Data data(model);
    const Eigen::VectorXd q = multibody::NeutralConfiguration(model);
    multibody::ForwardKinematics(model, data, q);
    multibody::CenterOfMass(model, data, q);
  }
}

void FuzzFootstepScenario(std::string_view input) {
  static const FuzzInputFile file("scenario.yaml");
  planning::FootstepScenario::Load(file.Write(input));
}

void FuzzOccupancyScenario(std::string_view input) {
  static const FuzzInputFile file("scenario.yaml");
  perception::OccupancyScenario::FromYaml(file.Write(input));
}

void FuzzWalkingModel(std::string_view input) {
  static const auto file = [] {
    auto f = std::make_unique<FuzzInputFile>("walking.yaml");
    f->Link("cairn_humanoid.urdf", kSource + "/data/robots/cairn_humanoid.urdf");
    return f;
  }();
  planning::WalkingModel::Load(file->Write(input));
}

void FuzzMaterialRegistry(std::string_view input) {
  static const FuzzInputFile file("materials.yaml");
  const perception::MaterialRegistry registry = perception::MaterialRegistry::LoadYaml(file.Write(input));
  for (const std::string& label : registry.labels()) registry.IndexOf(label);
}

void FuzzBuiltinSegmenter(std::string_view input) {
  static const FuzzInputFile file("segmenter.yaml");
  const perception::BuiltinMaterialSegmenter segmenter = perception::BuiltinMaterialSegmenter::Load(file.Write(input));
  // A 32 x 24 grey ramp: small enough to keep the harness fast, large enough for a few patches.
  cv::Mat image(24, 32, CV_8UC1);
  for (int y = 0; y < image.rows; ++y) {
    for (int x = 0; x < image.cols; ++x) image.at<std::uint8_t>(y, x) = static_cast<std::uint8_t>(7 * x + 3 * y);
  }
  segmenter.Segment(image);
}

void FuzzOnnxSegmenter(std::string_view input) {
  static const auto file = [] {
    auto f = std::make_unique<FuzzInputFile>("segmenter.yaml");
    f->Link("tiny_material_net.onnx", kSource + "/data/models/tiny_material_net.onnx");
    return f;
  }();
  perception::OnnxMaterialSegmenter::Load(file->Write(input));
}

void FuzzTransitionOracle(std::string_view input) {
  static const FuzzInputFile file("table.oracle");
  const planning::TransitionOracle oracle = planning::TransitionOracle::Load(
      file.Write(WithPayloadChecksum(std::string(input))), HumanoidWalkingModel(), kOracleObjective,
      FuzzOracleGrid());
  // The planner's uses of a loaded table: lookups inside, on and outside the grid, and the heuristic's bounds.
  for (const double mu : {0.3, 0.5, 0.7, 1.0, 2.0}) {
    oracle.Evaluate({0.05, 0.22, 0.0, 0.0}, mu);
    oracle.Evaluate({0.1, 0.25, 0.0, 0.0}, mu);
    oracle.Evaluate({0.2, 0.22, 0.0, 0.0}, mu);
    oracle.cost_lower_bound(mu);
    oracle.stride_cost_lower_bound(mu);
  }
  oracle.min_cost_per_metre();
  oracle.min_cost_per_step();
}

void FuzzDisparityPng(std::string_view input) {
  static const FuzzInputFile file("disp2.png");
  const cv::Mat disparity = perception::LoadDisparityImage(file.Write(input), 8.0);
  perception::OcclusionFromGroundTruth(disparity, disparity);
}

namespace {

const std::string kShared = CAIRN_SHARED_DIR;

std::string ReadSeed(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("fuzz seed '" + path + "' cannot be read; it ships with the repository.");
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// The regular files directly in `folder` whose names end in `extension`, sorted by name.
std::vector<FuzzSeed> SeedsIn(const std::string& folder, const std::string& extension) {
  std::vector<std::string> paths;
  for (const auto& entry : std::filesystem::directory_iterator(folder)) {
    const std::string path = entry.path().string();
    if (entry.is_regular_file() && path.size() > extension.size() &&
        path.compare(path.size() - extension.size(), extension.size(), extension) == 0) {
      paths.push_back(path);
    }
  }
  std::sort(paths.begin(), paths.end());
  std::vector<FuzzSeed> seeds;
  for (const std::string& path : paths) seeds.push_back({std::filesystem::path(path).filename().string(), ReadSeed(path)});
  return seeds;
}

std::vector<FuzzSeed> SeedFiles(const std::vector<std::string>& paths) {
  std::vector<FuzzSeed> seeds;
  for (const std::string& path : paths) seeds.push_back({std::filesystem::path(path).filename().string(), ReadSeed(path)});
  return seeds;
}

std::vector<FuzzSeed> UrdfSeeds() { return SeedFiles({kSource + "/data/robots/cairn_humanoid.urdf"}); }
std::vector<FuzzSeed> FootstepScenarioSeeds() { return SeedsIn(kSource + "/examples/scenarios", ".yaml"); }
std::vector<FuzzSeed> OccupancyScenarioSeeds() { return SeedsIn(kSource + "/examples/scenarios/occupancy", ".yaml"); }
std::vector<FuzzSeed> WalkingModelSeeds() { return SeedFiles({kSource + "/data/robots/cairn_humanoid_walking.yaml"}); }

std::vector<FuzzSeed> MaterialRegistrySeeds() {
  // The registry has no shipped file: its seed is the thesis' table as SaveYaml writes it.
  const FuzzInputFile scratch("materials.yaml");
  const std::string path = scratch.Write("");
  perception::MaterialRegistry::ThesisTable33().SaveYaml(path);
  return {{"thesis_table_3_3.yaml", ReadSeed(path)}};
}

std::vector<FuzzSeed> BuiltinSegmenterSeeds() {
  return SeedFiles({kSource + "/data/models/builtin_material_segmenter.yaml"});
}
std::vector<FuzzSeed> OnnxSegmenterSeeds() { return SeedFiles({kSource + "/data/models/tiny_material_net.yaml"}); }

std::vector<FuzzSeed> TransitionOracleSeeds() {
  // Built, not shipped: the table must match the current walking model's hash and the harness's grid.
  planning::OracleBuildOptions options;
  options.num_threads = 1;
  const std::string table =
      planning::TransitionOracle::Build(HumanoidWalkingModel(), kOracleObjective, FuzzOracleGrid(), options)
          .Serialize();
  return {{"humanoid_8_entries.oracle", table}};
}

std::vector<FuzzSeed> DisparityPngSeeds() {
  // The smallest of the Middlebury ground truths in shared/data (4 kB to 10 kB each).
  return SeedFiles({kShared + "/data/middlebury/tsukuba/disp2.png", kShared + "/data/middlebury/venus/disp2.png"});
}

}  // namespace

const std::vector<FuzzTarget>& FuzzTargets() {
  static const std::vector<FuzzTarget> targets = {
      {"urdf", FuzzUrdf, UrdfSeeds},
      {"footstep_scenario", FuzzFootstepScenario, FootstepScenarioSeeds},
      {"occupancy_scenario", FuzzOccupancyScenario, OccupancyScenarioSeeds},
      {"walking_model", FuzzWalkingModel, WalkingModelSeeds},
      {"material_registry", FuzzMaterialRegistry, MaterialRegistrySeeds},
      {"builtin_segmenter", FuzzBuiltinSegmenter, BuiltinSegmenterSeeds},
      {"onnx_segmenter", FuzzOnnxSegmenter, OnnxSegmenterSeeds},
      {"transition_oracle", FuzzTransitionOracle, TransitionOracleSeeds},
      {"disparity_png", FuzzDisparityPng, DisparityPngSeeds},
  };
  return targets;
}

}  // namespace cairn::fuzz
