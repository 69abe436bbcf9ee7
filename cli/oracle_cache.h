#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "cairn/planning/locomotion/transition_oracle.h"
#include "cairn/planning/locomotion/transition_source.h"
#include "cairn/planning/locomotion/walking_model.h"
#include "cairn/planning/locomotion/walking_objective.h"
#include "cairn/planning/scenarios/footstep_scenario.h"

namespace cairn::cli {

/// $XDG_CACHE_HOME/cairn/oracles, else ~/.cache/cairn/oracles, else a folder in the working directory.
std::string DefaultOracleCache();

/// The oracle sources the commands offer, the analytic default first: "model", "plant", "pipeline".
std::vector<std::string> OracleSourceNames();

/// The oracle source named `name` (one of OracleSourceNames()): null for the analytic model; for "plant" and
/// "pipeline", periodic gaits of `model`'s robot (its URDF with a floating base) under the joint controller of
/// `control_yaml`, at the timings t_ds x t_sw (empty: the source's defaults), walked in the plant or only planned.
/// Throws as the URDF parser, the controller and PlantTransitionSource do (naming the file or value).
std::shared_ptr<const planning::TransitionSource> OracleSource(
    const std::string& name, const std::shared_ptr<const planning::WalkingModel>& model,
    const std::string& control_yaml, planning::WalkingObjective objective, std::vector<double> t_ds = {},
    std::vector<double> t_sw = {});

/// A source's default grid: OracleGrid::Default for the analytic model (null), PlantTransitionSource::DefaultGrid
/// for the gait sources.
planning::OracleGrid DefaultOracleGrid(const planning::TransitionSource* source, const planning::WalkingModel& model);

/// The humanoid's joint-controller YAML in the data folder.
std::string DefaultControlYaml();

/// The oracle file of a source and grid in the cache folder: "<robot>-<objective>.oracle" for the analytic model,
/// "<robot>-<objective>-<source name>.oracle" for another source, each on its DefaultOracleGrid; any other grid
/// adds "-grid-<OracleGrid::Fingerprint()>" before ".oracle", so a table of another grid never replaces the
/// cached default one (or another grid's).
std::string OracleCachePath(const std::string& cache, const planning::WalkingModel& model,
                            planning::WalkingObjective objective, const planning::TransitionSource* source,
                            const planning::OracleGrid& grid);

/// The oracle from the cache folder, or built (with a progress bar) and saved there by
/// TransitionOracle::LoadOrBuild, which creates the folder. A cache that cannot be created or written is no reason
/// to fail: the library warns on stderr and the table is used from memory, not kept. `source` null: the analytic
/// model; no `grid`: the source's DefaultOracleGrid.
planning::TransitionOracle LoadOrBuildOracle(const std::string& cache, const planning::WalkingModel& model,
                                             planning::WalkingObjective objective,
                                             std::shared_ptr<const planning::TransitionSource> source = nullptr,
                                             std::optional<planning::OracleGrid> grid = std::nullopt);

/// Which oracle a planning command uses: `--oracle-cache`, `--oracle-source`, `--oracle-grid` (plan, walk, run).
struct OracleChoice {
  std::string cache;   ///< "" : DefaultOracleCache()
  std::string source;  ///< one of OracleSourceNames(); "": not given (the scenario's, else the analytic model)
  std::string grid;    ///< grid YAML; "": the source's default grid

  /// Takes the scenario's `oracle:` when --oracle-source was not given. Throws std::invalid_argument naming the
  /// scenario's file when its source is not one of OracleSourceNames().
  void Resolve(const planning::FootstepScenario& scenario);

  /// The source measures gaits ("plant", "pipeline") rather than evaluating the analytic model, so the SLSQP
  /// refinement, which optimises the analytic cost, does not apply to its plans.
  bool measured() const;
};

/// Declares the three options of `choice` on `app`.
void AddOracleOptions(CLI::App& app, OracleChoice* choice);

/// LoadOrBuildOracle for the choice (a gait source with the humanoid's controller and default timings). Throws
/// naming --oracle-grid when its file is missing or bad.
planning::TransitionOracle LoadChosenOracle(const OracleChoice& choice,
                                            const std::shared_ptr<const planning::WalkingModel>& model,
                                            planning::WalkingObjective objective);

}  // namespace cairn::cli
