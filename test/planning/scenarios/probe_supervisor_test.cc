#include "cairn/planning/scenarios/probe_supervisor.h"

#include <cmath>
#include <limits>
#include <memory>

#include <gtest/gtest.h>

#include "cairn/perception/terrain/grid_map.h"
#include "cairn/planning/scenarios/path_follower.h"
#include "cairn/systems/analysis/simulator.h"
#include "expect_throws.h"

namespace cairn::planning {
namespace {

// A 2 m x 2 m map at 10 cm around the origin with a 3 x 2-cell patch of plants at x in [0.5, 0.8), y in [-0.1, 0.1)
// and a second, single-cell patch (segmentation noise: below min_cluster_points) at (-0.55, 0.55).
perception::GridMap PlantsMap() {
  perception::GridMap map(Eigen::Vector2i(20, 20), 0.1, Eigen::Vector2d::Zero());
  const int plants = map.AddLayer("semantic_plants", 0.0);
  map.AddLayer("semantic_water", 0.0);
  for (double x : {0.55, 0.65, 0.75}) {
    for (double y : {-0.05, 0.05}) {
      Eigen::Vector2i cell;
      map.CellOf(Eigen::Vector2d(x, y), &cell);
      map.at(plants, cell.x(), cell.y()) = 0.9;
    }
  }
  Eigen::Vector2i noise;
  map.CellOf(Eigen::Vector2d(-0.55, 0.55), &noise);
  map.at(plants, noise.x(), noise.y()) = 0.9;
  return map;
}

// Seed 001 §5.3: choose the nearest candidate in reach, pause the robot, wait for the probe's window, assign the
// measured C to the whole cluster, resume.
TEST(ProbeSupervisorTest, PausesProbesAndAssignsTheReadingToTheWholeCluster) {
  ProbingPlanner::Options options;
  options.reach = 1.0;
  const ProbeSupervisor supervisor(options, 0.5, 3, 0.1);
  auto context = supervisor.CreateDefaultContext();
  supervisor.get_map_input_port().FixValue(context.get(), PlantsMap());
  supervisor.get_robot_input_port().FixValue(context.get(), Eigen::Vector2d(0.0, 0.0));
  const double nan = std::numeric_limits<double>::quiet_NaN();
  supervisor.get_collapsibility_input_port().FixValue(context.get(), Eigen::Vector2d(nan, 0.0));
  systems::Simulator simulator(supervisor, std::move(context));
  const auto pause = [&] {
    return supervisor.get_pause_output_port().Eval<Eigen::VectorXd>(simulator.get_context())[0];
  };
  EXPECT_EQ(pause(), 0.0);

  simulator.AdvanceTo(0.05);  // the update at t = 0 decides to probe
  EXPECT_EQ(pause(), 1.0);
  const Eigen::VectorXd command =
      supervisor.get_probe_command_output_port().Eval<Eigen::VectorXd>(simulator.get_context());
  EXPECT_EQ(command[2], 1.0);
  EXPECT_GE(command[0], 0.5);  // on the plants, not on the single noisy cell
  EXPECT_LT(command[0], 0.8);
  EXPECT_LT(std::abs(command[1]), 0.1);

  simulator.AdvanceTo(0.25);  // no reading yet, and the window is still filling (3 periods)
  EXPECT_EQ(pause(), 1.0);
  EXPECT_TRUE(supervisor.get_probes_output_port()
                  .Eval<std::vector<perception::ProbedRegion>>(simulator.get_context())
                  .empty());
  supervisor.get_collapsibility_input_port().FixValue(&simulator.get_mutable_context(), Eigen::Vector2d(0.85, 20.0));
  simulator.AdvanceTo(0.35);
  EXPECT_EQ(pause(), 0.0);  // resumed
  const auto& probes =
      supervisor.get_probes_output_port().Eval<std::vector<perception::ProbedRegion>>(simulator.get_context());
  ASSERT_EQ(probes.size(), 1u);
  EXPECT_EQ(probes[0].collapsibility, 0.85);
  EXPECT_EQ(probes[0].points.size(), 6u);  // every cell of the cluster, not just the probed one
  for (const Eigen::Vector2d& p : probes[0].points) {
    EXPECT_GE(p.x(), 0.5);
    EXPECT_LT(p.x(), 0.8);
  }
  EXPECT_EQ(supervisor.memory(simulator.get_context()).probes_made, 1);

  CAIRN_EXPECT_THROWS_WITH(ProbeSupervisor(options, 0.5, 0, 0.1), std::invalid_argument, "probe_periods 0");
  CAIRN_EXPECT_THROWS_WITH(ProbeSupervisor(options, 0.5, 3, -1.0), std::invalid_argument, "period -1 s");
}

// The robot stands still while the supervisor's pause is on and walks on when it is off.
TEST(PathFollowerTest, StandsStillWhilePaused) {
  const PathFollower walker(Eigen::Vector2d::Zero(), 0.1, 0.1);
  auto context = walker.CreateDefaultContext();
  Eigen::Matrix2Xd path(2, 2);
  path << 0.0, 1.0,  //
      0.0, 0.0;
  walker.get_path_input_port().FixValue(context.get(), systems::Value<Eigen::Matrix2Xd>(path));
  walker.get_pause_input_port().FixValue(context.get(), Eigen::VectorXd::Constant(1, 1.0));
  systems::Simulator simulator(walker, std::move(context));
  const auto x = [&] { return walker.get_position_output_port().Eval<Eigen::VectorXd>(simulator.get_context())[0]; };
  simulator.AdvanceTo(0.55);
  EXPECT_EQ(x(), 0.0);
  walker.get_pause_input_port().FixValue(&simulator.get_mutable_context(), Eigen::VectorXd::Constant(1, 0.0));
  simulator.AdvanceTo(0.85);  // updates at 0.6, 0.7, 0.8
  EXPECT_NEAR(x(), 0.3, 1e-12);
}

}  // namespace
}  // namespace cairn::planning
