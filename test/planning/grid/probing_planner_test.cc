#include "cairn/planning/grid/probing_planner.h"

#include <gtest/gtest.h>

#include "expect_throws.h"

namespace cairn::planning {
namespace {

// Points on a 5 cm lattice filling [x0, x1) x [y0, y1).
void AddPatch(double x0, double x1, double y0, double y1, int label, std::vector<Eigen::Vector2d>* points,
              std::vector<int>* labels) {
  for (double x = x0; x < x1 - 1e-9; x += 0.05) {
    for (double y = y0; y < y1 - 1e-9; y += 0.05) {
      points->emplace_back(x, y);
      labels->push_back(label);
    }
  }
}

Eigen::Matrix2Xd ToMatrix(const std::vector<Eigen::Vector2d>& points) {
  Eigen::Matrix2Xd m(2, points.size());
  for (std::size_t k = 0; k < points.size(); ++k) m.col(k) = points[k];
  return m;
}

TEST(ProbingPlannerTest, ClustersDownSamplesAndChoosesTheNearestCandidate) {
  std::vector<Eigen::Vector2d> p;
  std::vector<int> labels;
  AddPatch(1.0, 2.0, 0.0, 1.0, 0, &p, &labels);   // plants
  AddPatch(2.0, 2.6, 0.0, 1.0, 1, &p, &labels);   // water touching them: another class, another cluster
  AddPatch(4.0, 4.5, 0.0, 0.5, 0, &p, &labels);   // far plants
  p.emplace_back(0.2, 0.2);
  labels.push_back(-1);  // not questionable
  const Eigen::Matrix2Xd points = ToMatrix(p);
  ProbingPlanner planner;
  const auto clusters = planner.FindClusters(points, labels);
  ASSERT_EQ(clusters.size(), 3u);
  EXPECT_EQ(clusters[0].label, 0);
  EXPECT_EQ(clusters[0].members.size(), 400u);
  EXPECT_EQ(clusters[1].label, 1);
  EXPECT_EQ(clusters[2].members.size(), 100u);
  // 1 m x 1 m at 0.3 m squares: the squares overlapping it (4 x 4), one candidate each.
  EXPECT_EQ(clusters[0].candidates.size(), 16u);
  const auto far = planner.Decide(clusters, points, Eigen::Vector2d(-1.0, 0.5));
  EXPECT_EQ(far.action, ProbingPlanner::Decision::Action::kApproach);
  EXPECT_EQ(far.cluster, 0);
  const auto near = planner.Decide(clusters, points, Eigen::Vector2d(0.5, 0.5));
  ASSERT_EQ(near.action, ProbingPlanner::Decision::Action::kProbe);
  EXPECT_LE(near.distance, planner.options().reach);
  EXPECT_LT(near.target.x(), 1.2);
  // After the probe the cluster's candidates are gone: the next target is the water.
  planner.RecordProbe(clusters[near.cluster], points, near.target, 0.9);
  const auto next = planner.Decide(clusters, points, Eigen::Vector2d(0.5, 0.5));
  EXPECT_EQ(next.cluster, 1);
  EXPECT_EQ(planner.TouchingProbe(clusters[0], points), 0);
  EXPECT_EQ(planner.TouchingProbe(clusters[1], points), -1);
}

TEST(ProbingPlannerTest, AGrownClusterInheritsItsProbe) {
  std::vector<Eigen::Vector2d> p;
  std::vector<int> labels;
  AddPatch(1.0, 1.5, 0.0, 0.5, 0, &p, &labels);
  ProbingPlanner planner;
  Eigen::Matrix2Xd points = ToMatrix(p);
  auto clusters = planner.FindClusters(points, labels);
  planner.RecordProbe(clusters[0], points, points.col(0), 0.2);
  AddPatch(1.5, 2.5, 0.0, 0.5, 0, &p, &labels);  // more of the same region comes into view
  points = ToMatrix(p);
  clusters = planner.FindClusters(points, labels);
  ASSERT_EQ(clusters.size(), 1u);
  EXPECT_EQ(planner.TouchingProbe(clusters[0], points), 0);
  EXPECT_EQ(planner.Decide(clusters, points, Eigen::Vector2d::Zero()).action,
            ProbingPlanner::Decision::Action::kNone);
}

TEST(ProbingPlannerTest, RejectsBadInput) {
  ProbingPlanner planner;
  CAIRN_EXPECT_THROWS_WITH(planner.FindClusters(Eigen::Matrix2Xd::Zero(2, 3), {0, 0}), std::invalid_argument,
                           "2 labels for 3 points");
  CAIRN_EXPECT_THROWS_WITH(ProbingPlanner(ProbingPlanner::Options{0.1, 0.3, -1.0, 3}), std::invalid_argument,
                           "reach -1 m must be in [1e-6, 1e6]");
  CAIRN_EXPECT_THROWS_WITH(planner.FindClusters(Eigen::Matrix2Xd::Constant(2, 1, 1e300), {0}), std::invalid_argument,
                           "point 0 (1e+300, 1e+300) must be finite and within +-1e+06 m");
  ProbingPlanner::Cluster stray;
  stray.members = {5};
  CAIRN_EXPECT_THROWS_WITH(planner.TouchingProbe(stray, Eigen::Matrix2Xd::Zero(2, 1)), std::invalid_argument,
                           "cluster member 5 is not a column of the 1 points");
  ProbingPlanner::Cluster c;
  CAIRN_EXPECT_THROWS_WITH(planner.RecordProbe(c, Eigen::Matrix2Xd::Zero(2, 1), Eigen::Vector2d::Zero(), 1.5),
                           std::invalid_argument, "collapsibility 1.5");
}

// A cluster_distance far larger than the point spacing puts every point into one bucket: the pairwise comparison
// would be quadratic (10^13 pairs for 4 million points), so the call is refused with the value and the fix.
TEST(ProbingPlannerTest, RefusesAClusterDistanceThatMakesTheWorkQuadratic) {
  const int n = 40000;  // 8e8 ordered pairs in one bucket, more than the limit of 2.7e8
  Eigen::Matrix2Xd points(2, n);
  for (int k = 0; k < n; ++k) points.col(k) = Eigen::Vector2d(0.01 * (k % 200), 0.01 * (k / 200));
  const std::vector<int> labels(n, 0);
  ProbingPlanner::Options options;
  options.cluster_distance = 1000.0;
  const ProbingPlanner huge(options);
  CAIRN_EXPECT_THROWS_WITH(huge.FindClusters(points, labels), std::invalid_argument,
                           "cluster_distance 1000 m needs 1.6e+09 point-pair comparisons, more than the limit");
  // The same points at a cluster distance near their spacing cluster into one.
  options.cluster_distance = 0.015;
  const auto clusters = ProbingPlanner(options).FindClusters(points, labels);
  ASSERT_EQ(clusters.size(), 1u);
  EXPECT_EQ(clusters[0].members.size(), static_cast<std::size_t>(n));
}

}  // namespace
}  // namespace cairn::planning
