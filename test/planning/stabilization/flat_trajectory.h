#pragma once

#include <cairn/planning/trajectory/optimize_whole_body_trajectory.h>

#include "../trajectory/test_robot.h"

namespace cairn::planning::test {

/// A whole-body trajectory optimised (Ipopt) for four straight 0.2 m steps on flat ground, once per process.
inline const WholeBodyTrajectory& FlatTrajectory() {
  static const WholeBodyTrajectory trajectory =
      OptimizeWholeBodyTrajectory(Humanoid(), StraightPlan(4, 0.2), {}, TrajectoryOptimizerOptions());
  return trajectory;
}

}  // namespace cairn::planning::test
