// Stabilizer as a block: the work runs in events, the output copies the state, the input's change is picked up.
#include <gtest/gtest.h>

#include <cairn/planning/stabilization/stabilizer.h>
#include <cairn/systems/analysis/simulator.h>

#include "expect_throws.h"
#include "flat_trajectory.h"

namespace cairn::planning {
namespace {

StabilizerOptions Cheap() {
  StabilizerOptions options;
  options.method = "none";
  options.control_period = 0.02;
  return options;
}

TEST(StabilizerTest, StabilisesOnForcedEventsAndTheOutputCopiesTheState) {
  const Stabilizer system(test::Humanoid(), Cheap());
  auto context = system.CreateDefaultContext();
  system.get_trajectory_input_port().FixValue(context.get(), test::FlatTrajectory());
  const auto& before = system.get_reference_output_port().Eval<StabilizedTrajectory>(*context);
  EXPECT_FALSE(before.report.success);
  EXPECT_TRUE(before.q.empty());
  system.ExecuteForcedEvents(context.get());
  const auto& after = system.get_reference_output_port().Eval<StabilizedTrajectory>(*context);
  ASSERT_TRUE(after.report.success) << after.report.message;
  EXPECT_EQ(after.q.size(), 161u);  // 3.2 s at 50 Hz
}

TEST(StabilizerTest, ATrajectoryThatWasNotFoundGivesAnEmptyReferenceThatSaysWhy) {
  const Stabilizer system(test::Humanoid(), Cheap());
  auto context = system.CreateDefaultContext();
  WholeBodyTrajectory missing;
  missing.report.message = "infeasible: stance 3 start, l_sole position off by 0.21 m";
  system.get_trajectory_input_port().FixValue(context.get(), missing);
  system.ExecuteForcedEvents(context.get());
  const auto& reference = system.get_reference_output_port().Eval<StabilizedTrajectory>(*context);
  EXPECT_FALSE(reference.report.success);
  EXPECT_EQ(reference.report.message, "no trajectory to stabilise: " + missing.report.message);
}

TEST(StabilizerTest, PicksUpAChangedInputAtTheNextStep) {
  const Stabilizer system(test::Humanoid(), Cheap());
  auto context = system.CreateDefaultContext();
  system.get_trajectory_input_port().FixValue(context.get(), WholeBodyTrajectory());
  systems::Simulator simulator(system, std::move(context));
  simulator.Initialize();
  EXPECT_FALSE(system.get_reference_output_port().Eval<StabilizedTrajectory>(simulator.get_context()).report.success);
  system.get_trajectory_input_port().FixValue(&simulator.get_mutable_context(), test::FlatTrajectory());
  simulator.AdvanceTo(0.01);
  EXPECT_TRUE(system.get_reference_output_port().Eval<StabilizedTrajectory>(simulator.get_context()).report.success);
}

TEST(StabilizerTest, RejectsBadConstruction) {
  CAIRN_EXPECT_THROWS_WITH(Stabilizer(nullptr, StabilizerOptions()), std::invalid_argument,
                           "Stabilizer: the robot model is null");
  StabilizerOptions options;
  options.interpolation = "linear";
  CAIRN_EXPECT_THROWS_WITH(Stabilizer(test::Humanoid(), options), std::invalid_argument,
                           "interpolation 'linear' is unknown; use hermite or spline");
}

}  // namespace
}  // namespace cairn::planning
