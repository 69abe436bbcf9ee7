// `cairn occupancy`: runs a synthetic stereo sequence through the cost-curve (or WTA) occupancy grid and prints
// precision and recall per frame (thesis section 4.4).

#include <chrono>
#include <cstdio>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "cairn/common/atomic_file.h"
#include "cairn/common/json_writer.h"
#include "cairn/common/number_text.h"
#include "cairn/perception/evaluation/occupancy_score.h"
#include "cairn/perception/occupancy/cost_curve_sensor_model.h"
#include "cairn/perception/occupancy/wta_range_sensor_model.h"
#include "cairn/perception/stereo/compute_confidence.h"
#include "cairn/perception/stereo/compute_cost_volume.h"
#include "cairn/perception/stereo/cost_samples.h"
#include "cairn/perception/synthetic/bars_scenario.h"
#include "cairn/perception/synthetic/occupancy_scenario.h"
#include "cairn/perception/synthetic/synthetic_stereo_renderer.h"
#include "choice_option.h"
#include "command_registry.h"
#include "file_checks.h"
#include "numeric_option.h"

namespace cairn::cli {
namespace {

struct OccupancyState {
  std::string scenario{"bars"};
  std::string model{"merrell"};
  double noise_variance{0.0};
  bool noise_given{false};
  double peak_ratio{1.5};
  int frames{20};
  bool frames_given{false};
  std::string cost{"btsad"};
  int window{9};
  std::string ply;
  bool json{false};
};

int RunOccupancy(const OccupancyState& s) {
  using namespace cairn::perception;
  const bool wta_model = s.model == "wta";
  if (s.scenario != "bars") CheckInputFile("--scenario", s.scenario, "'bars' or a scenario YAML file");
  if (!s.ply.empty()) CheckOutputFile("--ply", s.ply);
  const ConfidenceModelType type = wta_model ? ConfidenceModelType::kMerrell : ParseConfidenceModelType(s.model);
  const CostFunction cost = ParseCostFunction(s.cost);
  OccupancyScenario scenario;
  if (s.scenario == "bars") {
    scenario = BarsScenario::Make(s.frames).ToOccupancyScenario();
  } else {
    scenario = OccupancyScenario::FromYaml(s.scenario);
    if (s.frames_given) {
      if (s.frames > static_cast<int>(scenario.trajectory.size())) {
        throw std::invalid_argument("--frames " + cairn::FormatShort(s.frames) + ": scenario '" + s.scenario + "' has " +
                                    cairn::FormatShort(scenario.trajectory.size()) + " frames; ask for 1 to that many");
      }
      scenario.trajectory.resize(static_cast<std::size_t>(s.frames));
    }
  }
  if (s.noise_given) scenario.noise_variance = s.noise_variance;
  const SyntheticStereoRenderer renderer(scenario.calibration, scenario.width, scenario.height,
                                         scenario.noise_variance, scenario.seed);
  CostVolumeOptions options;
  options.cost = cost;
  options.window = s.window;
  options.min_disparity = scenario.min_disparity;
  options.max_disparity = scenario.max_disparity;
  OccupancyGrid grid(scenario.grid_min_corner, scenario.grid_resolution, scenario.grid_dims);
  const std::vector<uint8_t> truth = RasterizeScene(scenario.scene, grid);
  WtaRangeSensorModel::Options wta_options;
  wta_options.min_peak_ratio = s.peak_ratio;
  const WtaRangeSensorModel wta_sensor(wta_options);
  const CostCurveSensorModel cost_curve_sensor;
  DisparityVolume costs;
  DisparityVolume confidence;
  WtaResult wta;
  double total_ms = 0.0;
  OccupancyScore score;
  // The JSON document is printed whole at the end, so a failing frame leaves no half-written object.
  JsonWriter json;
  json.BeginObject().Key("scenario").String(s.scenario).Key("model").String(s.model);
  json.Key("noise_var").Number(scenario.noise_variance).Key("frames").BeginArray();
  for (std::size_t f = 0; f < scenario.trajectory.size(); ++f) {
    const auto frame = renderer.Render(scenario.scene, scenario.trajectory[f], static_cast<int>(f));
    const auto start = std::chrono::steady_clock::now();
    ComputeCostVolume(frame.left, frame.right, options, &costs);
    ComputeWinnerTakeAll(costs, WtaOptions{}, &wta);
    if (wta_model) {
      wta_sensor.Integrate(wta, scenario.min_disparity, scenario.max_disparity, scenario.calibration, frame.X_WC,
                           &grid);
    } else {
      std::vector<float> samples;
      CollectConsistentWtaCosts(costs, wta, &samples);
      const auto model = ConfidenceModel::FitMaximumLikelihood(type, cost, samples);
      ComputeConfidence(costs, model, &confidence);
      cost_curve_sensor.Integrate(confidence, scenario.calibration, frame.X_WC, &grid);
    }
    const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    total_ms += ms;
    score = ScoreOccupancy(grid, truth);
    if (s.json) {
      json.BeginObject().Key("frame").Integer(f).Key("precision").Number(score.precision, JsonWriter::Fixed(4));
      json.Key("recall").Number(score.recall, JsonWriter::Fixed(4)).Key("ms").Number(ms, JsonWriter::Fixed(2));
      json.EndObject();
    } else {
      std::printf("frame %2zu  precision %.3f  recall %.3f  (%.1f ms)\n", f, score.precision, score.recall, ms);
    }
  }
  if (s.json) {
    json.EndArray().Key("precision").Number(score.precision, JsonWriter::Fixed(4));
    json.Key("recall").Number(score.recall, JsonWriter::Fixed(4));
    json.Key("ms_per_frame").Number(total_ms / static_cast<double>(scenario.trajectory.size()), JsonWriter::Fixed(2));
    std::printf("%s\n", json.EndObject().text().c_str());
  } else {
    std::printf("final     precision %.3f  recall %.3f  (tp %zu, fp %zu, n %zu); %.1f ms per frame (stereo + grid)\n",
                score.precision, score.recall, score.true_positives, score.false_positives, score.num_occupied,
                total_ms / static_cast<double>(scenario.trajectory.size()));
  }
  if (!s.ply.empty()) grid.WritePly(s.ply);
  return 0;
}

}  // namespace

void RegisterOccupancyCommand(CommandRegistry* registry) {
  registry->Add("occupancy", "Fuse a synthetic stereo sequence into an occupancy grid and score it",
                [](CLI::App& app) -> CommandAction {
                  auto s = std::make_shared<OccupancyState>();
                  app.add_option("--scenario", s->scenario,
                                 "bars (thesis Figs. 4.7/4.8) or a YAML file (docs/occupancy_scenarios.md)")
                      ->capture_default_str();
                  AddChoiceOption(app, "--model", &s->model, "Sensor model: cost-curve (fitted by maximum likelihood) "
                                  "or winner-take-all ranges", {"merrell", "matthies", "exp", "hsm", "wta"});
                  CLI::Option* noise = AddNumberOption(app, "--noise-var", &s->noise_variance,
                                                       "Gaussian image noise variance (0..255 scale); overrides the "
                                                       "scenario's", NumberRange::Closed(0.0, 255.0 * 255.0));
                  AddNumberOption(app, "--peak-ratio", &s->peak_ratio, "WTA model: minimum peak ratio (0: off)",
                                  NumberRange::Closed(0.0, 100.0));
                  CLI::Option* frames =
                      AddNumberOption(app, "--frames", &s->frames, "Number of frames (YAML: the first N of the file's)",
                                      NumberRange::Closed(1, perception::OccupancyScenario::kMaxFrames));
                  AddChoiceOption(app, "--cost", &s->cost, "Window cost", {"ssd", "btsad"});
                  AddNumberOption(app, "--window", &s->window, "Window side (ssd: at most 181)",
                                  NumberRange::Closed(1, 2051).OddOnly());
                  app.add_option("--ply", s->ply, "Write the final occupied cells to this PLY file");
                  app.add_flag("--json", s->json, "Print one JSON object");
                  return [s, noise, frames] {
                    s->noise_given = noise->count() > 0;
                    s->frames_given = frames->count() > 0;
                    return RunOccupancy(*s);
                  };
                });
}

}  // namespace cairn::cli
