// BalanceFeedback's and GravityFeedforward's outputs run at every plant step (1 ms) of the walk: once their
// per-context scratch exists they allocate nothing. Counted by replacing the global operator new in this test program.

#include <atomic>
#include <cmath>
#include <cstdlib>
#include <memory>
#include <new>
#include <vector>

#include <gtest/gtest.h>

#include <cairn/multibody/configuration.h>
#include <cairn/multibody/plant/sole_state.h>
#include <cairn/planning/walk/balance_feedback.h>
#include <cairn/planning/walk/gravity_feedforward.h>
#include <cairn/systems/framework/value.h>

#include "../trajectory/test_robot.h"

namespace {
std::atomic<long> g_allocations{0};
}  // namespace

void* operator new(std::size_t size) {
  g_allocations.fetch_add(1, std::memory_order_relaxed);
  if (void* p = std::malloc(size == 0 ? 1 : size)) return p;
  throw std::bad_alloc();
}
// GCC (at -O1 with sanitizers) sees free() of what a new-expression returned and warns, not knowing that the
// replacement operator new above allocates with malloc.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmismatched-new-delete"
#endif
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic pop
#endif

namespace cairn::planning {
namespace {

TEST(BalanceFeedbackAllocationTest, TheOutputAllocatesNothingAfterTheFirstStep) {
  const auto model = test::Humanoid();
  const BalanceFeedback feedback(model);
  auto context = feedback.CreateDefaultContext();
  Eigen::VectorXd planned = Eigen::VectorXd::Zero(model->nq() + model->nv());
  planned.head(model->nq()) = multibody::NeutralConfiguration(*model);
  planned[2] = 0.8;
  Eigen::VectorXd measured = planned;
  measured[0] += 0.03;  // the COM and both soles off the plan: every term of the feedback works
  measured[model->nq() + 4] = 0.1;
  std::vector<multibody::SoleState> soles(2);
  soles[0].loaded = soles[1].loaded = true;
  feedback.get_reference_input_port().FixValue(context.get(), planned);
  feedback.get_state_input_port().FixValue(context.get(), measured);
  feedback.get_contacts_input_port().FixValue(context.get(), systems::Value<std::vector<multibody::SoleState>>(soles));
  const auto value = feedback.get_reference_output_port().Allocate();
  feedback.get_reference_output_port().Calc(*context, value.get());  // warm-up: the per-context scratch
  const long before = g_allocations.load();
  for (int step = 0; step < 10; ++step) feedback.get_reference_output_port().Calc(*context, value.get());
  EXPECT_EQ(g_allocations.load() - before, 0);
  const long start = g_allocations.load();
  (void)feedback.Correct(planned, measured, true, true);  // the offline entry point allocates its own Data
  EXPECT_GT(g_allocations.load(), start);  // the counter sees allocations at all
}

// The same with one foot up, so that the swing leg's term works too.
TEST(BalanceFeedbackAllocationTest, TheSwingTermAllocatesNothing) {
  const auto model = test::Humanoid();
  BalanceFeedbackOptions options;
  options.swing_orientation_gain = options.swing_position_gain = 1.0;
  const BalanceFeedback feedback(model, options);
  auto context = feedback.CreateDefaultContext();
  Eigen::VectorXd planned = Eigen::VectorXd::Zero(model->nq() + model->nv());
  planned.head(model->nq()) = multibody::NeutralConfiguration(*model);
  planned[2] = 0.8;
  Eigen::VectorXd measured = planned;
  measured[3] = std::cos(0.025);  // the base pitched 0.05 rad: a rotation error for the swing sole
  measured[5] = std::sin(0.025);
  measured[0] += 0.02;
  std::vector<multibody::SoleState> soles(2);
  soles[0].loaded = true;
  feedback.get_reference_input_port().FixValue(context.get(), planned);
  feedback.get_state_input_port().FixValue(context.get(), measured);
  feedback.get_contacts_input_port().FixValue(context.get(), systems::Value<std::vector<multibody::SoleState>>(soles));
  const auto value = feedback.get_reference_output_port().Allocate();
  feedback.get_reference_output_port().Calc(*context, value.get());
  const long before = g_allocations.load();
  for (int step = 0; step < 10; ++step) feedback.get_reference_output_port().Calc(*context, value.get());
  EXPECT_EQ(g_allocations.load() - before, 0);
}

// GravityFeedforward's output runs at every plant step too.
TEST(GravityFeedforwardAllocationTest, TheOutputAllocatesNothingAfterTheFirstStep) {
  const auto model = test::Humanoid();
  const GravityFeedforward feedforward(model, {"l_sole", "r_sole"});
  auto context = feedforward.CreateDefaultContext();
  Eigen::VectorXd state = Eigen::VectorXd::Zero(model->nq() + model->nv());
  state.head(model->nq()) = multibody::NeutralConfiguration(*model);
  std::vector<multibody::SoleState> soles(2);
  soles[1].loaded = true;
  feedforward.get_state_input_port().FixValue(context.get(), state);
  feedforward.get_contacts_input_port().FixValue(context.get(),
                                                 systems::Value<std::vector<multibody::SoleState>>(soles));
  const auto value = feedforward.get_torque_output_port().Allocate();
  feedforward.get_torque_output_port().Calc(*context, value.get());
  const long before = g_allocations.load();
  for (int step = 0; step < 10; ++step) feedforward.get_torque_output_port().Calc(*context, value.get());
  EXPECT_EQ(g_allocations.load() - before, 0);
}

}  // namespace
}  // namespace cairn::planning
