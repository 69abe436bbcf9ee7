#include "oracle_cache.h"

#include <cstdlib>
#include <iostream>

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

TransitionOracle LoadOrBuildOracle(const std::string& cache, const WalkingModel& model, WalkingObjective objective) {
  const OracleGrid grid = OracleGrid::Default(model);
  const std::string path = cache + "/" + model.name() + "-" + to_string(objective) + ".oracle";
  OracleBuildOptions build;
  ProgressBar bar = ProgressBar::ForStderr("building the transition oracle");
  build.progress = [&bar](std::size_t done, std::size_t total) { bar.Update(done, total); };
  return TransitionOracle::LoadOrBuild(path, model, objective, grid, build, &std::cerr);
}

}  // namespace cairn::cli
