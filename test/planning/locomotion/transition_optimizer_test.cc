#include "cairn/planning/locomotion/transition_optimizer.h"

#include <cmath>

#include <gtest/gtest.h>

#include "cairn/planning/locomotion/step_evaluator.h"

#include "../support/shared_oracle.h"
#include "expect_throws.h"

namespace cairn::planning {
namespace {

class TransitionOptimizerTest : public ::testing::Test {
 protected:
  const WalkingModel* model_ = test::SharedWalkingModel().get();
};

TEST_F(TransitionOptimizerTest, RespectsFrictionAndCostFallsWithMu) {
  const StepDisplacement d{0.25, 0.2, 0.0, 0.0};
  StepEvaluator evaluator(*model_);
  double previous = INFINITY;
  for (double mu : {0.05, 0.08, 0.12, 0.2, 1.0}) {
    const TransitionCost c = OptimizeTransition(*model_, d, mu, WalkingObjective::kComWorkPlusHeat);
    ASSERT_TRUE(c.feasible) << mu;
    EXPECT_LE(c.rcof, mu + 1e-9);
    EXPECT_LE(c.cost, previous * (1.0 + 1e-9)) << mu;
    previous = c.cost;
    // The returned parameters reproduce the reported step.
    const StepEvaluation& e = evaluator.Evaluate(d, c.parameters);
    EXPECT_TRUE(e.feasible);
    EXPECT_DOUBLE_EQ(e.com_work + e.heat, c.cost);
    EXPECT_DOUBLE_EQ(e.rcof, c.rcof);
    EXPECT_DOUBLE_EQ(c.duration, c.parameters.t_ds + c.parameters.t_sw);
  }
  // Slippery ground asks for more double support (thesis 2.4.2: slower, with increased double support).
  const TransitionCost ice = OptimizeTransition(*model_, d, 0.06, WalkingObjective::kComWorkPlusHeat);
  const TransitionCost ground = OptimizeTransition(*model_, d, 1.0, WalkingObjective::kComWorkPlusHeat);
  EXPECT_GT(ice.parameters.t_ds, ground.parameters.t_ds + 0.2);
}

TEST_F(TransitionOptimizerTest, InfeasibleFrictionOrReach) {
  EXPECT_FALSE(OptimizeTransition(*model_, {0.25, 0.2, 0.0, 0.0}, 0.01, WalkingObjective::kComWork).feasible);
  EXPECT_FALSE(OptimizeTransition(*model_, {0.25, 0.2, 0.0, 0.0}, 0.0, WalkingObjective::kComWork).feasible);
  EXPECT_FALSE(OptimizeTransition(*model_, {0.45, 0.2, 0.0, 0.0}, 1.0, WalkingObjective::kComWork).feasible);
  EXPECT_FALSE(OptimizeTransition(*model_, {0.05, 0.2, 0.1, 0.0}, 1.0, WalkingObjective::kComWork).feasible);
  // A 0.1 m step up on a 0.2 m run is a 27-degree slope: it needs mu > tan(27 deg) = 0.5.
  EXPECT_FALSE(OptimizeTransition(*model_, {0.2, 0.2, 0.1, 0.0}, 0.45, WalkingObjective::kComWork).feasible);
  EXPECT_TRUE(OptimizeTransition(*model_, {0.2, 0.2, 0.1, 0.0}, 1.0, WalkingObjective::kComWork).feasible);
}

TEST_F(TransitionOptimizerTest, ObjectivesChooseDifferentSteps) {
  const StepDisplacement d{0.15, 0.2, 0.0, 0.0};
  const TransitionCost time = OptimizeTransition(*model_, d, 1.0, WalkingObjective::kTravelTime);
  ASSERT_TRUE(time.feasible);
  EXPECT_NEAR(time.cost, model_->parameter_lower().t_ds + model_->parameter_lower().t_sw, 1e-6);
  EXPECT_NEAR(time.duration, time.cost, 1e-12);
  const TransitionCost work = OptimizeTransition(*model_, d, 1.0, WalkingObjective::kComWork);
  const TransitionCost heat = OptimizeTransition(*model_, d, 1.0, WalkingObjective::kComWorkPlusHeat);
  const TransitionCost torque = OptimizeTransition(*model_, d, 1.0, WalkingObjective::kSquaredTorque);
  ASSERT_TRUE(work.feasible && heat.feasible && torque.feasible);
  // E_COM alone makes slow steps cheap; the heat term makes them expensive.
  EXPECT_GT(work.duration, heat.duration);
  EXPECT_LE(work.com_work, heat.com_work + 1e-9);
  EXPECT_LE(heat.cost, work.com_work + work.heat + 1e-9);
}

TEST_F(TransitionOptimizerTest, WarmStartRefinesLocally) {
  const StepDisplacement d{0.2, 0.22, 0.0, 0.0};
  const StepParameters start{0.6, 1.2, 0.74};
  StepEvaluator evaluator(*model_);
  const StepEvaluation& e = evaluator.Evaluate(d, start);
  ASSERT_TRUE(e.feasible && e.rcof <= 0.12);
  const double start_cost = e.com_work + e.heat;
  const TransitionCost refined = OptimizeTransition(*model_, d, 0.12, WalkingObjective::kComWorkPlusHeat, &start);
  ASSERT_TRUE(refined.feasible);
  EXPECT_LT(refined.cost, start_cost);
  EXPECT_LE(refined.rcof, 0.12 + 1e-9);
  const TransitionCost global = OptimizeTransition(*model_, d, 0.12, WalkingObjective::kComWorkPlusHeat);
  EXPECT_NEAR(refined.cost, global.cost, 1e-3 * global.cost);
}

TEST_F(TransitionOptimizerTest, RejectsBadArguments) {
  CAIRN_EXPECT_THROWS_WITH(OptimizeTransition(*model_, {0.2, 0.2, 0.0, 0.0}, -0.1, WalkingObjective::kComWork),
                           std::invalid_argument, "mu_allowed is -0.1", ">= 0");
  CAIRN_EXPECT_THROWS_WITH(OptimizeTransition(*model_, {0.2, 0.2, 0.0, 0.0}, NAN, WalkingObjective::kComWork),
                           std::invalid_argument, "mu_allowed");
  CAIRN_EXPECT_THROWS_WITH(OptimizeTransition(*model_, {0.2, INFINITY, 0.0, 0.0}, 0.5, WalkingObjective::kComWork),
                           std::invalid_argument, "dy is not finite");
  const StepParameters outside{3.0, 1.0, 0.7};
  CAIRN_EXPECT_THROWS_WITH(
      OptimizeTransition(*model_, {0.2, 0.2, 0.0, 0.0}, 0.5, WalkingObjective::kComWork, &outside),
      std::invalid_argument, "warm start", "outside the model's parameter bounds");
}

TEST(WalkingObjectiveTest, NamesRoundTripAndSuggest) {
  for (const std::string& name : WalkingObjectiveNames()) EXPECT_EQ(to_string(ParseWalkingObjective(name)), name);
  EXPECT_EQ(ParseWalkingObjective("ecom_heat"), WalkingObjective::kComWorkPlusHeat);
  CAIRN_EXPECT_THROWS_WITH(ParseWalkingObjective("ecom_heet"), std::invalid_argument, "'ecom_heet'",
                           "did you mean 'ecom_heat'", "'ecom', 'ecom_heat', 'time', 'torque'");
}

}  // namespace
}  // namespace cairn::planning
