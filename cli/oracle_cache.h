#pragma once

#include <string>

#include "cairn/planning/locomotion/transition_oracle.h"
#include "cairn/planning/locomotion/walking_model.h"
#include "cairn/planning/locomotion/walking_objective.h"

namespace cairn::cli {

/// $XDG_CACHE_HOME/cairn/oracles, else ~/.cache/cairn/oracles, else a folder in the working directory.
std::string DefaultOracleCache();

/// The oracle from the cache folder, or built (with a progress bar) and saved there by
/// TransitionOracle::LoadOrBuild, which creates the folder. A cache that cannot be created or written is no reason
/// to fail: the library warns on stderr and the table is used from memory, not kept.
planning::TransitionOracle LoadOrBuildOracle(const std::string& cache, const planning::WalkingModel& model,
                                             planning::WalkingObjective objective);

}  // namespace cairn::cli
