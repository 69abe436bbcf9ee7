// Every scenario shipped in examples/scenarios/ planned to optimality with the project's humanoid and its default
// transition oracle (objective E_COM + heat). The optimal costs are known answers: they were computed by the
// planner before its search was made faster (the relaxed-chain and stride heuristic alone, 0.4-1.8 million
// expansions each) and must not change, because the search's speed-ups (a tighter admissible heuristic) change
// how the optimum is found, never what it is. The tolerance is the oracle's rounding: the same plan summed in
// another order, or an equally cheap plan, agrees to far better than 1e-6 J.

#include <cstdint>
#include <cstdio>
#include <limits>
#include <memory>
#include <string>

#include <gtest/gtest.h>

#include <cairn/planning/footstep/plan_footsteps.h>
#include <cairn/planning/footstep/stance_graph.h>
#include <cairn/planning/scenarios/footstep_scenario.h>

#include "../support/shared_oracle.h"
#include "test_paths.h"

namespace cairn::planning {
namespace {

const std::string kScenarios = std::string(CAIRN_SOURCE_DIR) + "/examples/scenarios/";
constexpr double kCostTolerance = 1e-6;  // J

BipedGeometry GeometryOf(const WalkingModel& model) {
  BipedGeometry geometry;
  geometry.foot_length = model.foot_length();
  geometry.foot_width = model.foot_width();
  geometry.body_half_extents = model.body_half_extents();
  geometry.body_bottom = model.body_box_bottom();
  return geometry;
}

struct KnownOptimum {
  const char* scenario;
  double cost;  // J (E_COM + heat), before refinement
  int steps;
};

// Computed with the planner of commit 4ecd8ea (before the foothold-chain heuristic), no time limit.
constexpr KnownOptimum kKnownOptima[] = {
    {"flat", 786.733330851, 15},          {"ice_narrow_012", 792.128716497, 16}, {"ice_narrow_006", 830.475788756, 14},
    {"ice_wide_006", 864.436969638, 18},  {"slope_10", 1004.288558950, 10},      {"slope_20", 1451.334191317, 10},
    {"slope_25", 1700.718268030, 10},     {"stairs", 1336.894380263, 16},
};

class ShippedScenariosTest : public ::testing::TestWithParam<KnownOptimum> {
 protected:
  void SetUp() override {
    scenario_ = std::make_unique<FootstepScenario>(FootstepScenario::Load(kScenarios + GetParam().scenario + ".yaml"));
    terrain_ = std::make_unique<TerrainMap>(scenario_->BuildTerrain());
    options_ = scenario_->planner();
    options_.search.time_limit = std::numeric_limits<double>::infinity();
  }

  FootstepPlan Plan(const FootstepPlannerOptions& options) const {
    return PlanFootsteps(*terrain_, scenario_->start(), scenario_->goal(),
                         *test::SharedOracle(WalkingObjective::kComWorkPlusHeat),
                         GeometryOf(*test::SharedWalkingModel()), options);
  }

  std::unique_ptr<FootstepScenario> scenario_;
  std::unique_ptr<TerrainMap> terrain_;
  FootstepPlannerOptions options_;
};

TEST_P(ShippedScenariosTest, TheOptimalCostIsTheKnownOne) {
  const FootstepPlan plan = Plan(options_);
  std::printf("%-16s cost %.9f J  steps %zu  expansions %lld\n", GetParam().scenario, plan.cost, plan.steps.size(),
              static_cast<long long>(plan.statistics.expansions));
  ASSERT_TRUE(plan.found) << plan.reason;
  EXPECT_EQ(plan.statistics.epsilon, 1.0) << "the plan must be proven optimal";
  EXPECT_NEAR(plan.cost, GetParam().cost, kCostTolerance);
  EXPECT_EQ(static_cast<int>(plan.steps.size()), GetParam().steps);

  // The heuristic (all three of its bounds) never overestimates the cost to go along the optimal plan.
  StanceGraph graph(*terrain_, *test::SharedOracle(WalkingObjective::kComWorkPlusHeat),
                    GeometryOf(*test::SharedWalkingModel()), options_, scenario_->goal());
  double to_go = plan.cost;
  for (int k = -1; k < static_cast<int>(plan.steps.size()); ++k) {
    if (k >= 0) to_go -= plan.steps[k].transition.cost;
    const Stance s = k >= 0 ? plan.StanceAfter(k) : plan.start;
    StanceGraph::LatticeFoot left, right;
    ASSERT_TRUE(graph.Snap(s.left, &left) && graph.Snap(s.right, &right));
    // Before the first step, the stance whose newer foot stays put (the other one moves first).
    const FootSide newer = k >= 0 ? plan.steps[k].side : OtherSide(plan.first_side);
    const StanceGraph::Key key = newer == FootSide::kLeft ? graph.MakeKey(right, left, FootSide::kLeft)
                                                          : graph.MakeKey(left, right, FootSide::kRight);
    EXPECT_LE(graph.Heuristic(key), to_go + 1e-6) << "after step " << k;
    // The foothold-chain bound is nearly exact: only friction under the older foot is relaxed, so on level
    // ground of one friction it matches the cost to go but for its rounding margin; on slopes, whose steps it
    // prices by the lower bound over 0.1 mm of height, it stays within a few hundredths of a joule per step.
    const std::string name = GetParam().scenario;
    const double chain = graph.FootholdChainDistance(newer == FootSide::kLeft ? left : right, newer);
    if (name == "flat") {
      EXPECT_GE(chain, (1.0 - 2e-9) * to_go - 1e-6) << "after step " << k;
    } else if (name.rfind("slope", 0) == 0) {
      EXPECT_GE(chain, to_go - 0.1 * static_cast<double>(plan.steps.size() - k)) << "after step " << k;
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Scenarios, ShippedScenariosTest, ::testing::ValuesIn(kKnownOptima),
                         [](const ::testing::TestParamInfo<KnownOptimum>& info) { return std::string(info.param.scenario); });

// The same search twice gives the same plan, to the bit, including when an expansion budget stops it early.
TEST(ShippedScenariosDeterminismTest, RepeatedSearchesAgreeExactly) {
  const FootstepScenario scenario = FootstepScenario::Load(kScenarios + "ice_wide_006.yaml");
  const TerrainMap terrain = scenario.BuildTerrain();
  const auto oracle = test::SharedOracle(WalkingObjective::kComWorkPlusHeat);
  const BipedGeometry geometry = GeometryOf(*test::SharedWalkingModel());
  for (std::int64_t budget : {std::int64_t{200}, std::int64_t{-1}}) {
    FootstepPlannerOptions options = scenario.planner();
    options.search.time_limit = std::numeric_limits<double>::infinity();
    options.search.max_expansions = budget;
    const FootstepPlan a = PlanFootsteps(terrain, scenario.start(), scenario.goal(), *oracle, geometry, options);
    const FootstepPlan b = PlanFootsteps(terrain, scenario.start(), scenario.goal(), *oracle, geometry, options);
    ASSERT_TRUE(a.found) << a.reason;
    EXPECT_EQ(a.cost, b.cost) << "budget " << budget;
    EXPECT_EQ(a.statistics.epsilon, b.statistics.epsilon);
    EXPECT_EQ(a.statistics.expansions, b.statistics.expansions);
    ASSERT_EQ(a.steps.size(), b.steps.size());
    for (std::size_t k = 0; k < a.steps.size(); ++k) {
      EXPECT_EQ(a.steps[k].pose.x, b.steps[k].pose.x);
      EXPECT_EQ(a.steps[k].pose.y, b.steps[k].pose.y);
      EXPECT_EQ(a.steps[k].pose.theta, b.steps[k].pose.theta);
    }
  }
}

}  // namespace
}  // namespace cairn::planning
