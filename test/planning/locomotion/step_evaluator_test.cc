#include "cairn/planning/locomotion/step_evaluator.h"

#include <cmath>

#include <gtest/gtest.h>

#include "../support/shared_oracle.h"
#include "expect_throws.h"

namespace cairn::planning {
namespace {

class StepEvaluatorTest : public ::testing::Test {
 protected:
  const WalkingModel* model_ = test::SharedWalkingModel().get();
};

TEST_F(StepEvaluatorTest, LevelGroundRcofIsComOffsetOverHeight) {
  StepEvaluator evaluator(*model_);
  for (const StepDisplacement& d : {StepDisplacement{0.2, 0.2, 0.0, 0.0}, StepDisplacement{0.3, 0.25, 0.0, 0.3}}) {
    const StepParameters p{0.25, 1.0, 0.74};
    const StepEvaluation& e = evaluator.Evaluate(d, p);
    const WalkingPattern& pattern = evaluator.pattern();
    double offset = 0.0;
    for (int k = 0; k < pattern.com.cols(); ++k) {
      offset = std::max(offset, (pattern.com.col(k) - pattern.zmp.col(k)).head<2>().norm());
    }
    EXPECT_NEAR(e.rcof, offset / p.com_height, 1e-12);
    EXPECT_TRUE(e.feasible) << to_string(e.infeasibility);
  }
}

TEST_F(StepEvaluatorTest, ClimbingCostsAtLeastThePotentialEnergy) {
  StepEvaluator evaluator(*model_);
  const double m = model_->mass(), g = model_->gravity();
  for (double dz : {0.05, 0.10, 0.15, -0.05, -0.10}) {
    const StepEvaluation& e = evaluator.Evaluate({0.25, 0.2, dz, 0.0}, {0.4, 1.0, 0.70});
    EXPECT_GE(e.com_work, m * g * std::abs(dz) * (1.0 - 1e-12)) << dz;
  }
  // Energy rises steeply with step height (thesis Fig. 2.3): 10 cm up costs far more than a level step.
  const double level = evaluator.Evaluate({0.25, 0.2, 0.0, 0.0}, {0.4, 1.0, 0.70}).com_work;
  const double up = evaluator.Evaluate({0.25, 0.2, 0.10, 0.0}, {0.4, 1.0, 0.70}).com_work;
  EXPECT_GT(up, 3.0 * level);
}

// Thesis Figs. 2.4 and 2.5 on level ground: E_COM and RCOF fall with longer double support, RCOF falls with
// shorter steps.
TEST_F(StepEvaluatorTest, ReproducesTheThesisTrendsOnLevelGround) {
  StepEvaluator evaluator(*model_);
  double previous_work = INFINITY, previous_rcof = INFINITY;
  for (double t_ds : {0.09, 0.2, 0.4, 0.8, 1.6}) {
    const StepEvaluation& e = evaluator.Evaluate({0.2, 0.2, 0.0, 0.0}, {t_ds, 1.0, 0.74});
    EXPECT_LT(e.com_work, previous_work) << t_ds;
    EXPECT_LT(e.rcof, previous_rcof) << t_ds;
    previous_work = e.com_work;
    previous_rcof = e.rcof;
  }
  previous_rcof = INFINITY;
  for (double dx : {0.35, 0.25, 0.15, 0.05}) {
    const double rcof = evaluator.Evaluate({dx, 0.2, 0.0, 0.0}, {0.3, 1.0, 0.74}).rcof;
    EXPECT_LT(rcof, previous_rcof) << dx;
    previous_rcof = rcof;
  }
}

TEST_F(StepEvaluatorTest, HeatGrowsWithDurationAndWithBentKnees) {
  StepEvaluator evaluator(*model_);
  const StepDisplacement d{0.2, 0.2, 0.0, 0.0};
  const double short_swing = evaluator.Evaluate(d, {0.2, 0.9, 0.74}).heat;
  const double long_swing = evaluator.Evaluate(d, {0.2, 1.6, 0.74}).heat;
  const double long_support = evaluator.Evaluate(d, {1.2, 0.9, 0.74}).heat;
  EXPECT_GT(long_swing, 1.5 * short_swing);
  EXPECT_GT(long_support, short_swing);
  const double high = evaluator.Evaluate(d, {0.2, 0.9, 0.77}).heat;
  const double low = evaluator.Evaluate(d, {0.2, 0.9, 0.66}).heat;
  EXPECT_GT(low, 2.0 * high);
  // Heat and squared torque integrate the same torques; with one drive type their ratio is R / (r K)^2.
  const StepEvaluation& e = evaluator.Evaluate(d, {0.3, 1.1, 0.72});
  const MotorConstants& motor = model_->motor(0);
  EXPECT_NEAR(e.heat / e.squared_torque, motor.resistance / std::pow(motor.gear_ratio * motor.torque_constant, 2),
              1e-12);
  EXPECT_NEAR(e.duration, 1.4, 1e-15);
}

TEST_F(StepEvaluatorTest, ReportsWhyAStepIsInfeasible) {
  StepEvaluator evaluator(*model_);
  EXPECT_EQ(evaluator.Evaluate({0.5, 0.2, 0.0, 0.0}, {0.3, 1.0, 0.74}).infeasibility, StepInfeasibility::kOutOfReach);
  EXPECT_EQ(evaluator.Evaluate({0.05, 0.2, 0.1, 0.0}, {0.3, 1.0, 0.74}).infeasibility,
            StepInfeasibility::kSolesOverlap);
  EXPECT_EQ(evaluator.Evaluate({0.2, 0.2, 0.0, 0.0}, {0.05, 1.0, 0.74}).infeasibility,
            StepInfeasibility::kParametersOutOfBounds);
  // Straight legs cannot span a long step: the hips sit between the feet.
  const StepEvaluation& e = evaluator.Evaluate({0.35, 0.2, 0.0, 0.0}, {0.3, 1.0, 0.79});
  EXPECT_EQ(e.infeasibility, StepInfeasibility::kLegTooLong);
  EXPECT_GT(e.leg_length_max, model_->leg().leg_length_max);
  EXPECT_FALSE(e.feasible);
  // Stepping 10 cm up with the COM low: the leading leg would have to bend beyond the knee range.
  EXPECT_EQ(evaluator.Evaluate({0.2, 0.2, 0.1, 0.0}, {0.3, 1.0, 0.62}).infeasibility, StepInfeasibility::kLegTooShort);
  EXPECT_STREQ(to_string(StepInfeasibility::kLegTooShort), "leg too short");
}

TEST_F(StepEvaluatorTest, SlopesRaiseRcof) {
  StepEvaluator evaluator(*model_);
  const StepParameters p{0.6, 1.0, 0.70};
  const double level = evaluator.Evaluate({0.25, 0.2, 0.0, 0.0}, p).rcof;
  const double slope = evaluator.Evaluate({0.25, 0.2, 0.1, 0.0}, p).rcof;
  // Standing still on a slope of angle a needs tan(a); walking adds to it.
  EXPECT_GT(slope, 0.1 / 0.25);
  EXPECT_GT(slope, level);
}

}  // namespace
}  // namespace cairn::planning
