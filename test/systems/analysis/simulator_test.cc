#include "cairn/systems/analysis/simulator.h"

#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "cairn/systems/analysis/runge_kutta45_integrator.h"
#include "cairn/systems/analysis/runge_kutta4_integrator.h"
#include "cairn/systems/framework/diagram_builder.h"
#include "cairn/systems/framework/leaf_system.h"
#include "cairn/systems/primitives/constant_vector_source.h"
#include "cairn/systems/primitives/gain.h"
#include "cairn/systems/primitives/integrator.h"
#include "cairn/systems/primitives/vector_log_sink.h"
#include "cairn/systems/primitives/zero_order_hold.h"
#include "expect_throws.h"

namespace cairn::systems {
namespace {

// Records when each kind of event runs (in a per-context log) and counts discrete updates in its state.
class EventRecorder final : public LeafSystem {
 public:
  EventRecorder(double period, double offset) {
    log_ = DeclarePerContextStorage(Value<std::vector<std::string>>());
    count_ = DeclareDiscreteState(Eigen::VectorXd::Zero(1));
    DeclarePeriodicPublishEvent(period, offset, [this](const Context& c) { Record(c, "publish"); });
    DeclarePeriodicDiscreteUpdateEvent(period, offset, [this](const Context& c, DiscreteValues* next) {
      Record(c, "update");
      next->get_mutable_value(count_)[0] += 1.0;
    });
    DeclareInitializationPublishEvent([this](const Context& c) { Record(c, "init"); });
    DeclarePerStepPublishEvent([this](const Context& c) { Record(c, "step"); });
    DeclareForcedPublishEvent([this](const Context& c) { Record(c, "forced"); });
  }
  const std::vector<std::string>& Log(const Context& c) const {
    return GetPerContextStorage<std::vector<std::string>>(c, log_);
  }

 private:
  void Record(const Context& c, const std::string& what) const {
    char text[64];
    std::snprintf(text, sizeof(text), "%s@%.17g", what.c_str(), c.get_time());
    GetMutablePerContextStorage<std::vector<std::string>>(c, log_).push_back(text);
  }
  int log_;
  int count_;
};

TEST(SimulatorTest, PeriodicEventsLandExactlyOnTheirTimes) {
  EventRecorder recorder(0.1, 0.05);
  Simulator simulator(recorder);
  simulator.AdvanceTo(0.5);
  std::vector<std::string> updates;
  for (const auto& entry : recorder.Log(simulator.get_context())) {
    if (entry.rfind("update@", 0) == 0) updates.push_back(entry.substr(7));
  }
  // Updates at offset + k period for the times strictly before 0.5 reached so far (the one at 0.45 included;
  // an update due exactly at the boundary waits for the next AdvanceTo).
  ASSERT_EQ(updates.size(), 5u);
  for (int k = 0; k < 5; ++k) {
    char expected[32];
    std::snprintf(expected, sizeof(expected), "%.17g", 0.05 + k * 0.1);
    EXPECT_EQ(updates[k], expected);
  }
  EXPECT_EQ(simulator.get_context().get_discrete_state(0)[0], 5.0);
  EXPECT_EQ(simulator.get_context().get_time(), 0.5);
}

TEST(SimulatorTest, EventOrderIsInitializationThenUpdatesThenPublishes) {
  EventRecorder recorder(0.25, 0.0);
  Simulator simulator(recorder);
  simulator.AdvanceTo(0.5);
  recorder.ForcedPublish(simulator.get_context());
  const std::vector<std::string> expected = {"init@0",   "publish@0",    "step@0", "update@0", "publish@0.25",
                                             "step@0.25", "update@0.25", "publish@0.5", "step@0.5", "forced@0.5"};
  EXPECT_EQ(recorder.Log(simulator.get_context()), expected);
  // The update due at 0.5 happens when the simulation continues.
  simulator.AdvanceTo(0.6);
  EXPECT_EQ(simulator.get_context().get_discrete_state(0)[0], 3.0);
}

TEST(SimulatorTest, DiscreteUpdatesSeeTheStateBeforeAnyUpdate) {
  // Two holds in a ring swap their values every period only if both updates read the old values.
  DiagramBuilder builder;
  auto* a = builder.AddNamedSystem<ZeroOrderHold>("a", 1.0, 1);
  auto* b = builder.AddNamedSystem<ZeroOrderHold>("b", 1.0, 1);
  builder.Connect(*a, *b);
  builder.Connect(*b, *a);
  auto diagram = builder.Build();
  Simulator simulator(*diagram);
  diagram->GetMutableSubsystemContext(*a, &simulator.get_mutable_context()).SetDiscreteState(0, Eigen::VectorXd::Ones(1));
  simulator.AdvanceTo(0.5);  // The updates at t = 0 ran.
  EXPECT_EQ(diagram->GetSubsystemContext(*a, simulator.get_context()).get_discrete_state(0)[0], 0.0);
  EXPECT_EQ(diagram->GetSubsystemContext(*b, simulator.get_context()).get_discrete_state(0)[0], 1.0);
}

TEST(SimulatorTest, MonitorCanStopTheRun) {
  DiagramBuilder builder;
  auto* source = builder.AddSystem<ConstantVectorSource>(Eigen::VectorXd::Ones(1));
  auto* integrator = builder.AddNamedSystem<Integrator>("integrator", 1);
  builder.Connect(*source, *integrator);
  auto diagram = builder.Build();
  Simulator simulator(*diagram);
  simulator.set_monitor([](const Context& context) {
    return context.get_continuous_state_vector()[0] >= 0.25 ? MonitorResult::Stop("reached 0.25")
                                                             : MonitorResult::Continue();
  });
  const SimulatorStatus status = simulator.AdvanceTo(10.0);
  EXPECT_FALSE(status.reached_boundary_time());
  EXPECT_EQ(status.message, "reached 0.25");
  EXPECT_NEAR(status.time, 0.25, 1.5e-3);
}

TEST(SimulatorTest, LogsEveryStepAndRejectsBadArguments) {
  DiagramBuilder builder;
  auto* source = builder.AddSystem<ConstantVectorSource>(Eigen::VectorXd::Ones(1));
  auto* integrator = builder.AddNamedSystem<Integrator>("integrator", 1);
  builder.Connect(*source, *integrator);
  auto* logger = LogVectorOutput(integrator->get_output_port(), &builder, 0.1);
  auto diagram = builder.Build();
  Simulator simulator(*diagram);
  simulator.AdvanceTo(1.0);
  const VectorLog& log = logger->GetLog(diagram->GetSubsystemContext(*logger, simulator.get_context()));
  ASSERT_EQ(log.num_samples(), 11);
  for (int k = 0; k <= 10; ++k) EXPECT_NEAR(log.data()(0, k), 0.1 * k, 1e-12);

  CAIRN_EXPECT_THROWS_WITH(simulator.AdvanceTo(0.5), std::invalid_argument, "not before the current time");
  CAIRN_EXPECT_THROWS_WITH(simulator.set_target_realtime_rate(-1.0), std::invalid_argument, ">= 0");
  CAIRN_EXPECT_THROWS_WITH(simulator.get_mutable_integrator().set_target_accuracy(1e-3), std::logic_error,
                           "'rk4' has no error control", "RungeKutta45Integrator");
}

// A constant rate integrated: continuous state, no events.
std::unique_ptr<Diagram> Ramp() {
  DiagramBuilder builder;
  auto* source = builder.AddSystem<ConstantVectorSource>(Eigen::VectorXd::Ones(1));
  auto* integrator = builder.AddNamedSystem<Integrator>("integrator", 1);
  builder.Connect(*source, *integrator);
  return builder.Build();
}

TEST(SimulatorTest, RunsNeedingMoreStepsThanTheLimitAreRefusedBeforeTheyStart) {
  auto diagram = Ramp();
  Simulator simulator(*diagram);
  simulator.ResetIntegrator<RungeKutta4Integrator>(1e-20);
  // This ran "forever" before (1e21 steps).
  CAIRN_EXPECT_THROWS_WITH(simulator.AdvanceTo(10.0), std::invalid_argument, "AdvanceTo(10)",
                           "takes at least 1e+21 steps", "integrator steps of at most 1e-20 s",
                           "limit of 100000000", "Simulator::set_step_limit");
  EXPECT_EQ(simulator.get_context().get_time(), 0.0);
  simulator.ResetIntegrator<RungeKutta4Integrator>(1e-3);
  CAIRN_EXPECT_THROWS_WITH(simulator.AdvanceTo(1e300), std::invalid_argument, "takes at least 1e+303 steps");
  simulator.set_step_limit(999);
  CAIRN_EXPECT_THROWS_WITH(simulator.AdvanceTo(1.0), std::invalid_argument, "limit of 999");
  simulator.set_step_limit(1000);
  EXPECT_TRUE(simulator.AdvanceTo(1.0).reached_boundary_time());
  CAIRN_EXPECT_THROWS_WITH(simulator.set_step_limit(0), std::invalid_argument, "must be >= 1 step; got 0");
  CAIRN_EXPECT_THROWS_WITH(simulator.AdvanceTo(std::nan("")), std::invalid_argument, "AdvanceTo(nan)", "finite");
}

TEST(SimulatorTest, EventPeriodsCountTowardsTheLimitAndMustBeResolvable) {
  EventRecorder fast(1e-9, 0.0);
  Simulator simulator(fast);
  CAIRN_EXPECT_THROWS_WITH(simulator.AdvanceTo(1.0), std::invalid_argument, "takes at least 1e+09 steps",
                           "a periodic event of '<unnamed>' every 1e-09 s");
  EventRecorder slow(1e-3, 0.0);
  Simulator late(slow);
  late.get_mutable_context().SetTime(1e12);
  // At 1e12 event times 1e-3 apart coincide (1e-12 relative): the event search would never move on.
  CAIRN_EXPECT_THROWS_WITH(late.AdvanceTo(1e12 + 1.0), std::invalid_argument, "period 0.001 s",
                           "below the time resolution");
}

TEST(SimulatorTest, ARunReachingTheStepLimitStopsWithAMessage) {
  auto diagram = Ramp();
  Simulator simulator(*diagram);
  // The error-controlled integrator's steps cannot be known in advance; it starts at a hundredth of the maximum.
  simulator.ResetIntegrator<RungeKutta45Integrator>(100.0);
  simulator.set_step_limit(3);
  CAIRN_EXPECT_THROWS_WITH(simulator.AdvanceTo(100.0), std::runtime_error, "AdvanceTo(100) took 3 steps",
                           "reached only t = ");
}

TEST(SimulatorTest, VectorLogCapacityEndsARunThatLogsTooMuch) {
  DiagramBuilder builder;
  auto* source = builder.AddSystem<ConstantVectorSource>(Eigen::VectorXd::Ones(1));
  auto* integrator = builder.AddNamedSystem<Integrator>("integrator", 1);
  builder.Connect(*source, *integrator);
  LogVectorOutput(integrator->get_output_port(), &builder, 0.0, 5);
  auto diagram = builder.Build();
  Simulator simulator(*diagram);
  CAIRN_EXPECT_THROWS_WITH(simulator.AdvanceTo(1.0), std::runtime_error, "is full",
                           "capacity of 5 samples", "log less often");
}

TEST(SimulatorTest, RealTimePacingKeepsResults) {
  DiagramBuilder builder;
  auto* source = builder.AddSystem<ConstantVectorSource>(Eigen::VectorXd::Ones(1));
  auto* integrator = builder.AddNamedSystem<Integrator>("integrator", 1);
  builder.Connect(*source, *integrator);
  auto diagram = builder.Build();
  Simulator simulator(*diagram);
  simulator.set_target_realtime_rate(100.0);
  simulator.AdvanceTo(0.05);
  EXPECT_NEAR(simulator.get_context().get_continuous_state_vector()[0], 0.05, 1e-12);
}

// Counts in its discrete state every 0.1 s and reports, once the count reaches `stop_at`, a termination or a
// failure (as a plant reports a fall), or does the same from a publish event.
class Stopper final : public LeafSystem {
 public:
  enum class How { kTerminateInUpdate, kFailInUpdate, kTerminateInPublish };
  Stopper(How how, double stop_at) {
    DeclareDiscreteState(Eigen::VectorXd::Zero(1));
    DeclareStateOutputPort("count", 0);
    DeclarePeriodicDiscreteUpdateEvent(0.1, 0.0, [how, stop_at](const Context& c, DiscreteValues* next) {
      next->get_mutable_value(0)[0] += 1.0;
      if (how == How::kTerminateInPublish || next->get_mutable_value(0)[0] < stop_at) return EventStatus::Succeeded();
      return how == How::kTerminateInUpdate ? EventStatus::ReachedTermination("fell at count " + std::to_string(
                                                                                  static_cast<int>(stop_at)))
                                            : EventStatus::Failed("cannot go on at t = " + std::to_string(c.get_time()));
    });
    DeclarePeriodicPublishEvent(0.1, 0.05, [how, stop_at](const Context& c) {
      if (how == How::kTerminateInPublish && c.get_discrete_state(0)[0] >= stop_at) {
        return EventStatus::ReachedTermination("seen " + std::to_string(static_cast<int>(stop_at)));
      }
      return EventStatus::DidNothing();
    });
  }
};

TEST(SimulatorTest, EventHandlersCanEndTheRunWithAReason) {
  DiagramBuilder builder;
  builder.AddNamedSystem<Stopper>("plant", Stopper::How::kTerminateInUpdate, 4.0);
  auto diagram = builder.Build();
  Simulator simulator(*diagram);
  const SimulatorStatus status = simulator.AdvanceTo(10.0);
  EXPECT_EQ(status.reason, SimulatorStatus::Reason::kReachedTerminationCondition);
  EXPECT_NE(status.message.find("plant: fell at count 4"), std::string::npos) << status.message;
  // Updates at 0, 0.1, 0.2 and 0.3 s; the terminating update itself is applied.
  EXPECT_NEAR(status.time, 0.3, 1e-12);
  const auto& plant = diagram->GetSubsystemByName("plant");
  EXPECT_EQ(plant.get_output_port(0).Eval<Eigen::VectorXd>(diagram->GetSubsystemContext(plant, simulator.get_context()))[0],
            4.0);
}

TEST(SimulatorTest, AFailedUpdateIsNotAppliedAndIsReturned) {
  Stopper plant(Stopper::How::kFailInUpdate, 3.0);
  Simulator simulator(plant);
  const SimulatorStatus status = simulator.AdvanceTo(10.0);
  EXPECT_EQ(status.reason, SimulatorStatus::Reason::kEventHandlerFailed);
  EXPECT_NE(status.message.find("cannot go on at t = 0.2"), std::string::npos) << status.message;
  EXPECT_EQ(simulator.get_context().get_discrete_state(0)[0], 2.0);
}

TEST(SimulatorTest, APublishCanEndTheRun) {
  Stopper plant(Stopper::How::kTerminateInPublish, 2.0);
  Simulator simulator(plant);
  const SimulatorStatus status = simulator.AdvanceTo(10.0);
  EXPECT_EQ(status.reason, SimulatorStatus::Reason::kReachedTerminationCondition);
  EXPECT_NEAR(status.time, 0.15, 1e-12);
  EXPECT_NE(status.message.find("seen 2"), std::string::npos) << status.message;
}

}  // namespace
}  // namespace cairn::systems
