#include "cairn/planning/grid/grid_path_planner.h"

#include <cmath>

#include <gtest/gtest.h>

#include "cairn/systems/analysis/simulator.h"
#include "expect_throws.h"

namespace cairn::planning {
namespace {

TEST(GridPathPlannerTest, PlansAndCountsReplansWhenTheMapBlocksThePath) {
  GridPathPlanner planner(1.0, Eigen::Vector2d::Zero(), GridSearch::Options{}, 0.1);
  auto context = planner.CreateDefaultContext();
  Eigen::MatrixXd t = Eigen::MatrixXd::Ones(5, 3);
  planner.get_traversability_input_port().FixValue(context.get(), systems::Value<Eigen::MatrixXd>(t));
  planner.get_start_input_port().FixValue(context.get(), Eigen::Vector2d(0.5, 1.5));
  planner.get_goal_input_port().FixValue(context.get(), Eigen::Vector2d(4.5, 1.5));
  systems::Simulator simulator(planner, std::move(context));
  simulator.AdvanceTo(0.05);
  auto status = planner.get_status_output_port().Eval<Eigen::VectorXd>(simulator.get_context());
  EXPECT_EQ(status[0], 1.0);
  EXPECT_NEAR(status[1], 4.0, 1e-12);
  const auto& path = planner.get_path_output_port().Eval<Eigen::Matrix2Xd>(simulator.get_context());
  ASSERT_EQ(path.cols(), 5);
  EXPECT_TRUE(path.col(2).isApprox(Eigen::Vector2d(2.5, 1.5)));
  t(2, 1) = 0.0;  // the map changes under the path
  planner.get_traversability_input_port().FixValue(&simulator.get_mutable_context(), systems::Value<Eigen::MatrixXd>(t));
  simulator.AdvanceTo(0.15);
  status = planner.get_status_output_port().Eval<Eigen::VectorXd>(simulator.get_context());
  EXPECT_EQ(status[0], 1.0);
  EXPECT_EQ(status[2], 1.0);
  EXPECT_GT(status[1], 4.0);
  CAIRN_EXPECT_THROWS_WITH(GridPathPlanner(0.0, Eigen::Vector2d::Zero(), GridSearch::Options{}, 0.1),
                           std::invalid_argument, "resolution 0 m");
}

}  // namespace
}  // namespace cairn::planning
