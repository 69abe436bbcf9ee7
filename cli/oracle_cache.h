#pragma once

#include <memory>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "cairn/planning/locomotion/transition_oracle.h"
#include "cairn/planning/locomotion/transition_source.h"
#include "cairn/planning/locomotion/walking_model.h"
#include "cairn/planning/locomotion/walking_objective.h"

namespace cairn::cli {

/// $XDG_CACHE_HOME/cairn/oracles, else ~/.cache/cairn/oracles, else a folder in the working directory.
std::string DefaultOracleCache();

/// The `plant` oracle source of the commands: periodic gaits of `model`'s robot (its URDF with a floating base)
/// under the joint controller of `control_yaml`, at the timings t_ds x t_sw (empty: the source's defaults).
/// Throws as the URDF parser, the controller and PlantTransitionSource do (naming the file or value).
std::shared_ptr<const planning::TransitionSource> PlantOracleSource(
    const std::shared_ptr<const planning::WalkingModel>& model, const std::string& control_yaml,
    planning::WalkingObjective objective, std::vector<double> t_ds = {}, std::vector<double> t_sw = {});

/// The humanoid's joint-controller YAML in the data folder.
std::string DefaultControlYaml();

/// The oracle file of a source in the cache folder: "<robot>-<objective>.oracle" for the analytic model,
/// "<robot>-<objective>-<source name>.oracle" for another source.
std::string OracleCachePath(const std::string& cache, const planning::WalkingModel& model,
                            planning::WalkingObjective objective, const planning::TransitionSource* source);

/// The oracle from the cache folder, or built (with a progress bar) and saved there by
/// TransitionOracle::LoadOrBuild, which creates the folder. A cache that cannot be created or written is no reason
/// to fail: the library warns on stderr and the table is used from memory, not kept. `source` null: the analytic
/// model; `grid` empty (no dx values): OracleGrid::Default for the model source, PlantTransitionSource::DefaultGrid
/// for the plant.
planning::TransitionOracle LoadOrBuildOracle(const std::string& cache, const planning::WalkingModel& model,
                                             planning::WalkingObjective objective,
                                             std::shared_ptr<const planning::TransitionSource> source = nullptr,
                                             planning::OracleGrid grid = planning::OracleGrid());

/// Which oracle a planning command uses: `--oracle-cache`, `--oracle-source`, `--oracle-grid` (plan, walk, run).
struct OracleChoice {
  std::string cache;            ///< "" : DefaultOracleCache()
  std::string source{"model"};  ///< "model" or "plant"
  std::string grid;             ///< grid YAML; "": the source's default grid

  bool plant() const;
};

/// Declares the three options of `choice` on `app`.
void AddOracleOptions(CLI::App& app, OracleChoice* choice);

/// LoadOrBuildOracle for the choice (the plant source with the humanoid's controller and default timings). Throws
/// naming --oracle-grid when its file is missing or bad.
planning::TransitionOracle LoadChosenOracle(const OracleChoice& choice,
                                            const std::shared_ptr<const planning::WalkingModel>& model,
                                            planning::WalkingObjective objective);

}  // namespace cairn::cli
