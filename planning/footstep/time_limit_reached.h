#pragma once

#include <stdexcept>

namespace cairn::planning {

/// Thrown when a time limit stops set-up work before a search (rasterising a scenario's terrain, precomputing the
/// stance graph's heuristic) that cannot return a partial result. PlanFootsteps() turns it into a plan without
/// steps whose reason says where the time ran out; callers that do set-up of their own under the same budget
/// (FootstepScenario::BuildTerrain()) should do the same. The message says what was being done and how far it got.
class TimeLimitReached : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace cairn::planning
