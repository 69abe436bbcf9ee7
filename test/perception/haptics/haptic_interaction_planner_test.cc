#include "cairn/perception/haptics/haptic_interaction_planner.h"

#include <cmath>
#include <stdexcept>

#include "expect_throws.h"

namespace cairn::perception {
namespace {

constexpr double kPi = 3.14159265358979323846;

TEST(HapticInteractionPlannerTest, PaperDefaults) {
  const HapticInteractionPlanner::Options o;
  EXPECT_EQ(o.voxel, 0.04);
  EXPECT_EQ(o.min_candidate_spacing, 0.05);
  EXPECT_EQ(o.ground_offset, -0.1);
  EXPECT_EQ(o.sigma, 0.8);
  EXPECT_EQ(o.neighbour_radius, 0.1);
  EXPECT_EQ(o.theta_height, 0.3);
  EXPECT_EQ(o.theta_centroid, 0.2);
  EXPECT_EQ(o.theta_density, 0.5);
  EXPECT_EQ(o.push_distance, 0.05);
}

TEST(HapticInteractionPlannerTest, ScoresOfTwoPointsByHand) {
  const HapticInteractionPlanner planner;
  Eigen::Matrix3Xd points(3, 2);
  points << 0.01, 0.07,  //
      -0.1, -0.1,        //
      1.0, 1.0;          // 6 cm apart, in different 4 cm voxels, at the height g
  const std::vector<InteractionPoint> scored = planner.ScoreCandidates(points);
  ASSERT_EQ(scored.size(), 2u);
  const double sh = 1.0;                                               // eq. 16 at y = g
  const double sc = std::exp(-0.03 * 0.03 / (2.0 * 0.8 * 0.8));         // eq. 17, 3 cm from the centroid
  const double sd = 1.0 / (2.0 * kPi * 0.1 * 0.1 / (0.04 * 0.04));      // eq. 18: one neighbour of 39.27
  for (const InteractionPoint& p : scored) {
    EXPECT_DOUBLE_EQ(p.height_score, sh);
    EXPECT_NEAR(p.centroid_score, sc, 1e-12);
    EXPECT_NEAR(p.density_score, sd, 1e-12);
    EXPECT_NEAR(p.score, 0.3 * sh + 0.2 * sc + 0.5 * sd, 1e-12);  // eq. 19
  }
  // Equal scores keep the cloud's order.
  EXPECT_EQ(scored[0].p_C.x(), 0.01);
}

TEST(HapticInteractionPlannerTest, HeightScoreFallsAwayFromG) {
  const HapticInteractionPlanner planner;
  Eigen::Matrix3Xd point(3, 1);
  point << 0.01, 0.7, 1.0;  // 0.8 m (one σ) below g
  const std::vector<InteractionPoint> scored = planner.ScoreCandidates(point);
  ASSERT_EQ(scored.size(), 1u);
  // The voxel centroid is the point itself; the lone point is its own centroid and has no neighbours.
  EXPECT_NEAR(scored[0].height_score, std::exp(-0.5), 1e-12);
  EXPECT_DOUBLE_EQ(scored[0].centroid_score, 1.0);
  EXPECT_DOUBLE_EQ(scored[0].density_score, 0.0);
}

TEST(HapticInteractionPlannerTest, CandidatesAreSpacedAndDenseRegionsScoreHigher) {
  const HapticInteractionPlanner planner;
  // A dense 40 x 40 cm patch at x < 0 and a sparse row of points at x > 0.3.
  Eigen::Matrix3Xd points(3, 400 + 5);
  int n = 0;
  for (int i = 0; i < 20; ++i) {
    for (int j = 0; j < 20; ++j) points.col(n++) = Eigen::Vector3d(-0.4 + 0.02 * i, -0.1 + 0.02 * j, 1.0);
  }
  for (int i = 0; i < 5; ++i) points.col(n++) = Eigen::Vector3d(0.3 + 0.12 * i, -0.1, 1.0);
  const std::vector<InteractionPoint> scored = planner.ScoreCandidates(points);
  for (std::size_t i = 0; i < scored.size(); ++i) {
    for (std::size_t j = i + 1; j < scored.size(); ++j) {
      ASSERT_GE((scored[i].p_C - scored[j].p_C).norm(), 0.05);
    }
    if (i > 0) {
      EXPECT_GE(scored[i - 1].score, scored[i].score);
    }
  }
  EXPECT_LT(scored.front().p_C.x(), 0.0);
  EXPECT_GT(scored.back().p_C.x(), 0.25);
}

TEST(HapticInteractionPlannerTest, PruningThresholdIsAlphaTimesConfidence) {
  HapticInteractionPlanner::Options options;
  options.alpha = 0.5;
  const HapticInteractionPlanner planner(options);
  std::vector<InteractionPoint> sorted(4);
  const double scores[] = {0.9, 0.6, 0.45, 0.2};
  for (int i = 0; i < 4; ++i) sorted[i].score = scores[i];
  EXPECT_EQ(planner.Prune(sorted, 1.0).size(), 2u);   // > 0.5
  EXPECT_EQ(planner.Prune(sorted, 0.8).size(), 3u);   // > 0.4
  EXPECT_EQ(planner.Prune(sorted, 0.0).size(), 4u);   // an unknown object: touch everywhere
  EXPECT_EQ(planner.Prune(sorted, 1.0).front().score, 0.9);
  options.alpha = 2.0;
  EXPECT_EQ(HapticInteractionPlanner(options).Prune(sorted, 0.5).size(), 0u);  // > 1: trust the memory
}

TEST(HapticInteractionPlannerTest, ExecutionStartsRightmostThenNearest) {
  std::vector<InteractionPoint> points(4);
  const double xs[] = {0.0, 0.5, 0.2, -0.3};
  for (int i = 0; i < 4; ++i) points[i].p_C = Eigen::Vector3d(xs[i], 0.0, 1.0);
  const std::vector<InteractionPoint> order = HapticInteractionPlanner::ExecutionOrder(points);
  ASSERT_EQ(order.size(), 4u);
  EXPECT_EQ(order[0].p_C.x(), 0.5);
  EXPECT_EQ(order[1].p_C.x(), 0.2);
  EXPECT_EQ(order[2].p_C.x(), 0.0);
  EXPECT_EQ(order[3].p_C.x(), -0.3);
}

TEST(HapticInteractionPlannerTest, PlanPushesTargetsAlongTheOpticalAxis) {
  const HapticInteractionPlanner planner;
  Eigen::Matrix3Xd points(3, 2);
  points << 0.01, 0.07, -0.1, -0.1, 1.0, 1.0;
  const InteractionPlan plan = planner.Plan(points, 0.5);
  ASSERT_EQ(plan.selected.size(), 2u);
  EXPECT_EQ(plan.threshold, 0.5);
  EXPECT_NEAR(plan.targets_C[0].z(), 1.05, 1e-12);
  EXPECT_EQ(plan.selected[0].p_C.x(), 0.07);  // rightmost first
  EXPECT_TRUE(planner.Plan(points, 0.6).selected.empty());  // scores ~0.51 < 0.6
  EXPECT_TRUE(planner.Plan(Eigen::Matrix3Xd(3, 0), 0.0).candidates.empty());
}

TEST(HapticInteractionPlannerTest, BadOptionsNameTheValue) {
  HapticInteractionPlanner::Options options;
  options.theta_density = 0.6;
  CAIRN_EXPECT_THROWS_WITH(HapticInteractionPlanner{options}, std::invalid_argument, "is 1.1", "must sum to 1");
  options = {};
  options.sigma = 0.0;
  CAIRN_EXPECT_THROWS_WITH(HapticInteractionPlanner{options}, std::invalid_argument, "sigma is 0");
  options = {};
  options.alpha = -1.0;
  CAIRN_EXPECT_THROWS_WITH(HapticInteractionPlanner{options}, std::invalid_argument, "alpha is -1");
  const HapticInteractionPlanner planner;
  CAIRN_EXPECT_THROWS_WITH(planner.Prune({}, 1.5), std::invalid_argument, "confidence is 1.5");
}

}  // namespace
}  // namespace cairn::perception
