#include "cairn/planning/grid/grid_path_planner.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "cairn/common/number_text.h"
#include "cairn/systems/framework/state.h"

namespace cairn::planning {

GridPathPlanner::GridPathPlanner(double resolution, const Eigen::Vector2d& min_corner,
                                 const GridSearch::Options& options, double period)
    : resolution_(resolution), min_corner_(min_corner), search_(options) {
  if (!(period > 0.0) || !std::isfinite(period)) {
    throw std::invalid_argument("GridPathPlanner: period " + FormatShort(period) +
                                " s must be positive and finite (e.g. 0.2, the map's update period)");
  }
  if (!(resolution > 0.0) || !std::isfinite(resolution) || !min_corner.allFinite()) {
    throw std::invalid_argument("GridPathPlanner: resolution " + FormatShort(resolution) +
                                " m must be positive and finite, and the minimum corner finite");
  }
  DeclareAbstractInputPort("traversability", systems::Value<Eigen::MatrixXd>(Eigen::MatrixXd()));
  DeclareVectorInputPort("start", 2);
  DeclareVectorInputPort("goal", 2);
  plan_state_ = DeclareAbstractState(systems::Value<Plan>(Plan{}));
  const int s = plan_state_;
  const double res = resolution_;
  const Eigen::Vector2d corner = min_corner_;
  DeclareAbstractOutputPort(
      "path", systems::Value<Eigen::Matrix2Xd>(Eigen::Matrix2Xd()),
      [s, res, corner](const systems::Context& c, systems::AbstractValue* v) {
        const Plan& plan = c.get_abstract_state<Plan>(s);
        Eigen::Matrix2Xd& out = v->get_mutable_value<Eigen::Matrix2Xd>();
        out.resize(2, static_cast<Eigen::Index>(plan.path.cells.size()));
        for (std::size_t k = 0; k < plan.path.cells.size(); ++k) {
          out.col(static_cast<Eigen::Index>(k)) =
              corner + (plan.path.cells[k].cast<double>() + Eigen::Vector2d::Constant(0.5)) * res;
        }
      },
      {abstract_state_ticket(s)});
  DeclareVectorOutputPort(
      "status", 3,
      [s](const systems::Context& c, Eigen::VectorXd* y) {
        const Plan& plan = c.get_abstract_state<Plan>(s);
        (*y)[0] = plan.path.found ? 1.0 : 0.0;
        (*y)[1] = plan.path.cost;
        (*y)[2] = plan.replans;
      },
      {abstract_state_ticket(s)});
  DeclarePeriodicUnrestrictedUpdateEvent(period, 0.0, &GridPathPlanner::Update);
}

void GridPathPlanner::Update(const systems::Context& context, systems::State* next) const {
  TraversabilityGrid grid;
  grid.values = get_traversability_input_port().Eval<Eigen::MatrixXd>(context);
  grid.resolution = resolution_;
  grid.min_corner = min_corner_;
  const Eigen::VectorXd& start = get_start_input_port().Eval<Eigen::VectorXd>(context);
  const Eigen::VectorXd& goal = get_goal_input_port().Eval<Eigen::VectorXd>(context);
  grid.Validate();  // an empty or malformed map is reported as such, not as a start outside it
  const Eigen::Vector2i s = grid.CellOf(start.head<2>());
  const Eigen::Vector2i g = grid.CellOf(goal.head<2>());
  if (!grid.Contains(s) || !grid.Contains(g)) {
    throw std::invalid_argument("GridPathPlanner: the start (" + FormatShort(start[0]) + ", " + FormatShort(start[1]) +
                                ") or the goal (" + FormatShort(goal[0]) + ", " + FormatShort(goal[1]) +
                                ") is outside the map");
  }
  Plan& plan = next->get_mutable_abstract_state<Plan>(plan_state_);
  // What is left of the previous path, from the robot's cell on: blocked now means the map change forces a replan.
  if (plan.path.found) {
    auto it = std::find(plan.path.cells.begin(), plan.path.cells.end(), s);
    if (it != plan.path.cells.end()) {
      const std::vector<Eigen::Vector2i> rest(it, plan.path.cells.end());
      grid.Validate();
      if (std::isinf(search_.PathCost(grid, rest))) ++plan.replans;
    }
  }
  plan.path = search_.Plan(grid, s, g);
}

}  // namespace cairn::planning
