#include "oracle_cache.h"

#include <cstdlib>
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

std::shared_ptr<const TransitionSource> PlantOracleSource(const std::shared_ptr<const WalkingModel>& model,
                                                          const std::string& control_yaml,
                                                          WalkingObjective objective, std::vector<double> t_ds,
                                                          std::vector<double> t_sw) {
  CheckInputFile("--control", control_yaml, "a joint-controller YAML file");
  multibody::UrdfOptions urdf;
  urdf.floating_base = true;
  const auto robot = std::make_shared<const multibody::Model>(multibody::ParseUrdfFile(model->urdf_path(), urdf));
  const auto controller =
      std::make_shared<const multibody::JointPdController>(multibody::JointPdController::Load(*robot, control_yaml));
  const auto sampler = std::make_shared<const PlantGaitSampler>(model, robot, controller, objective);
  if (t_ds.empty()) t_ds = PlantTransitionSource::DefaultDoubleSupportTimes(*model);
  if (t_sw.empty()) t_sw = PlantTransitionSource::DefaultSwingTimes(*model);
  return std::make_shared<const PlantTransitionSource>(sampler, std::move(t_ds), std::move(t_sw));
}

std::string OracleCachePath(const std::string& cache, const WalkingModel& model, WalkingObjective objective,
                            const TransitionSource* source) {
  std::string name = model.name() + "-" + to_string(objective);
  if (source != nullptr && source->name() != TransitionOracle::kSource) name += "-" + source->name();
  return cache + "/" + name + ".oracle";
}

TransitionOracle LoadOrBuildOracle(const std::string& cache, const WalkingModel& model, WalkingObjective objective,
                                   std::shared_ptr<const TransitionSource> source, OracleGrid grid) {
  const bool plant = source != nullptr && source->name() == PlantTransitionSource::kName;
  if (grid.dx.empty()) grid = plant ? PlantTransitionSource::DefaultGrid(model) : OracleGrid::Default(model);
  const std::string path = OracleCachePath(cache, model, objective, source.get());
  OracleBuildOptions build;
  build.source = std::move(source);
  ProgressBar bar = ProgressBar::ForStderr(plant ? "walking the plant oracle's gaits" : "building the transition oracle");
  build.progress = [&bar](std::size_t done, std::size_t total) { bar.Update(done, total); };
  return TransitionOracle::LoadOrBuild(path, model, objective, grid, build, &std::cerr);
}

bool OracleChoice::plant() const { return source == PlantTransitionSource::kName; }

void AddOracleOptions(CLI::App& app, OracleChoice* choice) {
  app.add_option("--oracle-cache", choice->cache,
                 "Folder caching transition oracles (default $XDG_CACHE_HOME/cairn/oracles)");
  AddChoiceOption(app, "--oracle-source", &choice->source,
                  "Where the oracle's step costs come from: the analytic walking model, or periodic gaits walked in "
                  "the physics plant (built once into the cache: minutes; docs/oracle.md; skips the SLSQP "
                  "refinement, which optimises the analytic model's cost)",
                  {TransitionOracle::kSource, PlantTransitionSource::kName});
  app.add_option("--oracle-grid", choice->grid,
                 "Oracle grid YAML (default: the source's default grid; docs/oracle.md)");
}

TransitionOracle LoadChosenOracle(const OracleChoice& choice, const std::shared_ptr<const WalkingModel>& model,
                                  WalkingObjective objective) {
  OracleGrid grid;
  if (!choice.grid.empty()) {
    CheckInputFile("--oracle-grid", choice.grid, "an oracle grid YAML file");
    grid = OracleGrid::Load(choice.grid);
  }
  return LoadOrBuildOracle(choice.cache.empty() ? DefaultOracleCache() : choice.cache, *model, objective,
                           choice.plant() ? PlantOracleSource(model, DefaultControlYaml(), objective) : nullptr,
                           std::move(grid));
}

}  // namespace cairn::cli
