#pragma once

// The default transition oracle of the project's humanoid, built once per build tree and shared by every test
// process: ctest runs each test in its own process, possibly two at a time, so the first to arrive builds the
// table under an exclusive file lock and the others wait and then load it.

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <filesystem>
#include <iostream>
#include <memory>
#include <stdexcept>
#include <string>

#include <cairn/planning/locomotion/transition_oracle.h>
#include <cairn/planning/locomotion/walking_model.h>
#include <cairn/planning/locomotion/walking_objective.h>
#include "test_paths.h"

namespace cairn::planning::test {

inline std::string HumanoidWalkingYaml() {
  return std::string(CAIRN_SOURCE_DIR) + "/data/robots/cairn_humanoid_walking.yaml";
}

inline std::shared_ptr<const WalkingModel> SharedWalkingModel() {
  static const auto model = std::make_shared<const WalkingModel>(WalkingModel::Load(HumanoidWalkingYaml()));
  return model;
}

inline std::shared_ptr<const TransitionOracle> SharedOracle(WalkingObjective objective) {
  const std::shared_ptr<const WalkingModel> model = SharedWalkingModel();
  const std::string folder = std::string(CAIRN_BINARY_DIR) + "/test-oracle-cache";
  std::filesystem::create_directories(folder);
  const std::string path = folder + "/" + model->name() + "-" + to_string(objective) + ".oracle";
  const int lock = ::open((path + ".lock").c_str(), O_CREAT | O_RDWR, 0644);
  if (lock < 0 || ::flock(lock, LOCK_EX) != 0) throw std::runtime_error("cannot lock " + path + ".lock");
  std::shared_ptr<const TransitionOracle> oracle;
  try {
    oracle = std::make_shared<const TransitionOracle>(TransitionOracle::LoadOrBuild(
        path, *model, objective, OracleGrid::Default(*model), OracleBuildOptions{}, &std::cerr));
  } catch (...) {
    ::close(lock);
    throw;
  }
  ::close(lock);  // releases the lock
  return oracle;
}

}  // namespace cairn::planning::test
