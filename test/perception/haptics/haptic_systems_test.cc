// The haptic-affordance systems alone: fixed inputs, evaluated outputs, simulated updates.
#include <stdexcept>

#include "cairn/perception/haptics/affordance_memory.h"
#include "cairn/perception/haptics/change_detector.h"
#include "cairn/perception/haptics/interaction_planner.h"
#include "cairn/perception/haptics/object_descriptor.h"
#include "cairn/systems/analysis/simulator.h"
#include "cairn/systems/framework/value.h"
#include "expect_throws.h"

namespace cairn::perception {
namespace {

Eigen::Matrix3Xd Grid() {
  Eigen::Matrix3Xd points(3, 16 * 14);
  for (int l = 0; l < 14; ++l) {
    for (int c = 0; c < 16; ++c) points.col(l * 16 + c) = Eigen::Vector3d(0.02 * c, 0.02 * l, 0.5);
  }
  return points;
}

AffordanceDescriptor One(double n, double s, double d, double m) {
  return AffordanceDescriptor::FromValues(Eigen::Vector4d(n, s, d, m));
}

TEST(HapticSystemsTest, ObjectDescriptorComputesFromItsInput) {
  const ObjectDescriptor system;
  auto context = system.CreateDefaultContext();
  system.get_points_input_port().FixAbstractValue(context.get(), systems::Value<Eigen::Matrix3Xd>(Grid()));
  const auto& d = system.get_descriptor_output_port().Eval<AffordanceDescriptor>(*context);
  EXPECT_EQ(d.values(), AffordanceDescriptor::Compute(Grid(), AffordanceDescriptor::Options{}).values());
  EXPECT_EQ(system.get_object_output_port().Eval<Eigen::Matrix3Xd>(*context).cols(), 16 * 14);
}

TEST(HapticSystemsTest, AffordanceMemoryLearnsEachOutcomeOnce) {
  const AffordanceMemory system(TraversabilityMemory(TraversabilityMemory::Options{}, 1), 0.1);
  auto context = system.CreateDefaultContext();
  system.get_descriptor_input_port().FixValue(context.get(), One(2, 3, 1, 4));
  HapticOutcome outcome;
  outcome.sequence = 0;
  outcome.traversable = true;
  outcome.descriptor = One(2, 3, 1, 4);
  system.get_outcome_input_port().FixValue(context.get(), outcome);
  EXPECT_EQ(system.get_recall_output_port().Eval<AffordanceRecall>(*context).confidence, 0.0);
  systems::Simulator simulator(system, std::move(context));
  simulator.AdvanceTo(0.35);  // four updates, one outcome
  const auto& memory = system.get_memory_output_port().Eval<TraversabilityMemory>(simulator.get_context());
  EXPECT_EQ(memory.size(), 1);
  const auto& recall = system.get_recall_output_port().Eval<AffordanceRecall>(simulator.get_context());
  EXPECT_TRUE(recall.traversable);
  EXPECT_DOUBLE_EQ(recall.confidence, 1.0 / 5.0);  // one perfect neighbour over k = 5
  CAIRN_EXPECT_THROWS_WITH(AffordanceMemory(TraversabilityMemory(), 0.0), std::invalid_argument, "period 0 s");
}

TEST(HapticSystemsTest, InteractionPlannerPrunesByTheRecallConfidence) {
  const InteractionPlanner system;
  auto context = system.CreateDefaultContext();
  Eigen::Matrix3Xd object(3, 2);
  object << 0.01, 0.07, -0.1, -0.1, 1.0, 1.0;
  system.get_object_input_port().FixAbstractValue(context.get(), systems::Value<Eigen::Matrix3Xd>(object));
  AffordanceRecall recall;
  recall.confidence = 0.5;
  system.get_recall_input_port().FixValue(context.get(), recall);
  EXPECT_EQ(system.get_plan_output_port().Eval<InteractionPlan>(*context).selected.size(), 2u);
  recall.confidence = 0.9;
  system.get_recall_input_port().FixValue(context.get(), recall);
  EXPECT_TRUE(system.get_plan_output_port().Eval<InteractionPlan>(*context).selected.empty());
}

TEST(HapticSystemsTest, ChangeDetectorTakesTheReferenceFirst) {
  const ChangeDetector system(GistChangeDetector::Options{}, 0.1);
  auto context = system.CreateDefaultContext();
  system.get_points_input_port().FixAbstractValue(context.get(), systems::Value<Eigen::Matrix3Xd>(Grid()));
  systems::Simulator simulator(system, std::move(context));
  simulator.AdvanceTo(0.05);
  const Eigen::VectorXd first = system.get_change_output_port().Eval<Eigen::VectorXd>(simulator.get_context());
  EXPECT_DOUBLE_EQ(first[0], 1.0);  // 2 cm apart: one point per voxel
  system.get_points_input_port().FixAbstractValue(&simulator.get_mutable_context(),
                                                  systems::Value<Eigen::Matrix3Xd>(Eigen::Matrix3Xd(3, 0)));
  simulator.AdvanceTo(0.15);
  const Eigen::VectorXd second = system.get_change_output_port().Eval<Eigen::VectorXd>(simulator.get_context());
  EXPECT_DOUBLE_EQ(second[1], 1.0);
  EXPECT_EQ(second[2], 1.0);
}

}  // namespace
}  // namespace cairn::perception
