// TrajectoryOptimizer as a block: the solve runs in events and lives in state.
#include <gtest/gtest.h>

#include <cairn/planning/trajectory/trajectory_optimizer.h>
#include <cairn/systems/analysis/simulator.h>

#include "expect_throws.h"
#include "test_robot.h"

namespace cairn::planning {
namespace {

TEST(TrajectoryOptimizerTest, SolvesOnForcedEventsAndTheOutputOnlyCopiesTheState) {
  const TrajectoryOptimizer system(test::Humanoid(), TrajectoryOptimizerOptions());
  auto context = system.CreateDefaultContext();
  system.get_plan_input_port().FixValue(context.get(), test::StraightPlan(1, 0.15));
  system.get_environment_input_port().FixValue(context.get(), std::vector<EnvironmentBox>{});
  const auto& before = system.get_trajectory_output_port().Eval<WholeBodyTrajectory>(*context);
  EXPECT_FALSE(before.found);
  EXPECT_EQ(before.report.status, "not solved yet");
  system.ExecuteForcedEvents(context.get());
  const auto& after = system.get_trajectory_output_port().Eval<WholeBodyTrajectory>(*context);
  ASSERT_TRUE(after.found) << after.report.message;
  EXPECT_EQ(after.waypoints.size(), 3u);
  EXPECT_EQ(after.waypoints[1].contacts, std::vector<std::string>{"l_sole"});
  EXPECT_EQ(after.coordinate_names.size(), static_cast<std::size_t>(test::Humanoid()->nq()));
  // Changing the input does not re-solve by itself: the output follows the state.
  system.get_plan_input_port().FixValue(context.get(), FootstepPlan());
  EXPECT_TRUE(system.get_trajectory_output_port().Eval<WholeBodyTrajectory>(*context).found);
  system.ExecuteForcedEvents(context.get());
  EXPECT_EQ(system.get_trajectory_output_port().Eval<WholeBodyTrajectory>(*context).report.status, "no footstep plan");
}

TEST(TrajectoryOptimizerTest, SolvesWhenASimulatorInitializes) {
  const TrajectoryOptimizer system(test::Humanoid(), TrajectoryOptimizerOptions());
  auto context = system.CreateDefaultContext();
  system.get_plan_input_port().FixValue(context.get(), test::StraightPlan(0, 0.2));
  system.get_environment_input_port().FixValue(context.get(), std::vector<EnvironmentBox>{});
  systems::Simulator simulator(system, std::move(context));
  simulator.Initialize();
  const auto& trajectory = system.get_trajectory_output_port().Eval<WholeBodyTrajectory>(simulator.get_context());
  EXPECT_TRUE(trajectory.found) << trajectory.report.message;
  EXPECT_EQ(trajectory.waypoints.size(), 1u);
}

TEST(TrajectoryOptimizerTest, RejectsABadPeriod) {
  CAIRN_EXPECT_THROWS_WITH(TrajectoryOptimizer(test::Humanoid(), TrajectoryOptimizerOptions(), -1.0),
                           std::invalid_argument, "period -1 s must be finite and >= 0");
  CAIRN_EXPECT_THROWS_WITH(TrajectoryOptimizer(nullptr, TrajectoryOptimizerOptions()), std::invalid_argument,
                           "model is null");
  TrajectoryOptimizerOptions newton;
  newton.hessian = "newton";
  CAIRN_EXPECT_THROWS_WITH(ValidateTrajectoryOptimizerOptions(newton), std::invalid_argument,
                           "hessian is 'newton'; it must be 'gauss-newton', 'exact' or 'limited-memory'");
  newton.hessian = "gauss-newton";
  EXPECT_NO_THROW(ValidateTrajectoryOptimizerOptions(newton));
}

}  // namespace
}  // namespace cairn::planning
