#include "oracle_cache.h"

#include <algorithm>
#include <cstdlib>
#include <stdexcept>
#include <iostream>
#include <utility>

#include "cairn/multibody/plant/joint_pd_controller.h"
#include "cairn/multibody/urdf_parser.h"
#include "cairn/planning/walk/plant_transition_source.h"
#include "choice_option.h"
#include "data_directory.h"
#include "file_checks.h"
#include "progress_bar.h"

namespace cairn::cli {

using namespace cairn::planning;

std::string DefaultOracleCache() {
  if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg != nullptr && *xdg != '\0') {
    return std::string(xdg) + "/cairn/oracles";
  }
  if (const char* home = std::getenv("HOME"); home != nullptr && *home != '\0') {
    return std::string(home) + "/.cache/cairn/oracles";
  }
  return ".cairn-cache/oracles";
}

std::string DefaultControlYaml() { return DataDirectory() + "/robots/cairn_humanoid_control.yaml"; }

std::vector<std::string> OracleSourceNames() {
  return {TransitionOracle::kSource, PlantTransitionSource::kName, PlantTransitionSource::kPipelineName};
}

std::shared_ptr<const TransitionSource> OracleSource(const std::string& name,
                                                     const std::shared_ptr<const WalkingModel>& model,
                                                     const std::string& control_yaml, WalkingObjective objective,
                                                     std::vector<double> t_ds, std::vector<double> t_sw) {
  if (name == TransitionOracle::kSource) return nullptr;
  PlantTransitionSource::Mode mode;
  if (name == PlantTransitionSource::kName) {
    mode = PlantTransitionSource::Mode::kPlant;
  } else if (name == PlantTransitionSource::kPipelineName) {
    mode = PlantTransitionSource::Mode::kPipeline;
  } else {
    throw std::invalid_argument("unknown oracle source '" + name + "'; use model, plant or pipeline");
  }
  CheckInputFile("--control", control_yaml, "a joint-controller YAML file");
  multibody::UrdfOptions urdf;
  urdf.floating_base = true;
  const auto robot = std::make_shared<const multibody::Model>(multibody::ParseUrdfFile(model->urdf_path(), urdf));
  const auto controller =
      std::make_shared<const multibody::JointPdController>(multibody::JointPdController::Load(*robot, control_yaml));
  const auto sampler = std::make_shared<const PlantGaitSampler>(model, robot, controller, objective);
  if (t_ds.empty()) t_ds = PlantTransitionSource::DefaultDoubleSupportTimes(*model);
  if (t_sw.empty()) t_sw = PlantTransitionSource::DefaultSwingTimes(*model);
  return std::make_shared<const PlantTransitionSource>(sampler, std::move(t_ds), std::move(t_sw), mode);
}

OracleGrid DefaultOracleGrid(const TransitionSource* source, const WalkingModel& model) {
  return source == nullptr ? OracleGrid::Default(model) : PlantTransitionSource::DefaultGrid(model);
}

std::string OracleCachePath(const std::string& cache, const WalkingModel& model, WalkingObjective objective,
                            const TransitionSource* source, const OracleGrid& grid) {
  std::string name = model.name() + "-" + to_string(objective);
  if (source != nullptr && source->name() != TransitionOracle::kSource) name += "-" + source->name();
  if (grid != DefaultOracleGrid(source, model)) name += "-grid-" + grid.Fingerprint();
  return cache + "/" + name + ".oracle";
}

TransitionOracle LoadOrBuildOracle(const std::string& cache, const WalkingModel& model, WalkingObjective objective,
                                   std::shared_ptr<const TransitionSource> source, std::optional<OracleGrid> grid) {
  if (!grid) grid = DefaultOracleGrid(source.get(), model);
  const std::string path = OracleCachePath(cache, model, objective, source.get(), *grid);
  const std::string task = source == nullptr ? std::string("building the transition oracle")
                                             : "measuring the " + source->name() + " oracle's gaits";
  OracleBuildOptions build;
  build.source = std::move(source);
  ProgressBar bar = ProgressBar::ForStderr(task);
  build.progress = [&bar](std::size_t done, std::size_t total) { bar.Update(done, total); };
  return TransitionOracle::LoadOrBuild(path, model, objective, *grid, build, &std::cerr);
}

void OracleChoice::Resolve(const FootstepScenario& scenario) {
  if (!source.empty()) return;
  const std::vector<std::string> names = OracleSourceNames();
  if (std::find(names.begin(), names.end(), scenario.oracle()) == names.end()) {
    throw std::invalid_argument("scenario " + scenario.path() + ": oracle '" + scenario.oracle() +
                                "' is not one of model, plant, pipeline");
  }
  source = scenario.oracle();
}

bool OracleChoice::measured() const { return !source.empty() && source != TransitionOracle::kSource; }

void AddOracleOptions(CLI::App& app, OracleChoice* choice) {
  app.add_option("--oracle-cache", choice->cache,
                 "Folder caching transition oracles (default $XDG_CACHE_HOME/cairn/oracles)");
  AddChoiceOption(app, "--oracle-source", &choice->source,
                  "Where the oracle's step costs come from: the analytic walking model, periodic gaits walked in "
                  "the physics plant, or the same gaits only optimised and stabilised (pipeline; objectives torque, "
                  "ecom, time). Gait tables are built once into the cache (minutes; docs/oracle.md) and skip the "
                  "SLSQP refinement, which optimises the analytic model's cost. Default: the scenario's `oracle:`, "
                  "else model",
                  OracleSourceNames());
  app.add_option("--oracle-grid", choice->grid,
                 "Oracle grid YAML (default: the source's default grid; docs/oracle.md)");
}

TransitionOracle LoadChosenOracle(const OracleChoice& choice, const std::shared_ptr<const WalkingModel>& model,
                                  WalkingObjective objective) {
  std::optional<OracleGrid> grid;
  if (!choice.grid.empty()) {
    CheckInputFile("--oracle-grid", choice.grid, "an oracle grid YAML file");
    grid = OracleGrid::Load(choice.grid);
  }
  return LoadOrBuildOracle(choice.cache.empty() ? DefaultOracleCache() : choice.cache, *model, objective,
                           OracleSource(choice.source.empty() ? TransitionOracle::kSource : choice.source, model,
                                        DefaultControlYaml(), objective),
                           std::move(grid));
}

}  // namespace cairn::cli
