#include <cairn/planning/trajectory/trajectory_optimizer.h>

#include <cmath>
#include <stdexcept>
#include <utility>

#include <cairn/common/number_text.h>
#include <cairn/planning/trajectory/optimize_whole_body_trajectory.h>
#include <cairn/systems/framework/state.h>

namespace cairn::planning {

namespace {
WholeBodyTrajectory NotSolvedYet() {
  WholeBodyTrajectory trajectory;
  trajectory.report.status = "not solved yet";
  trajectory.report.message = "not solved yet: the solve runs at initialization, on forced events or periodically";
  return trajectory;
}
}  // namespace

TrajectoryOptimizer::TrajectoryOptimizer(std::shared_ptr<const multibody::Model> model,
                                         const TrajectoryOptimizerOptions& options, double period)
    : model_(std::move(model)), options_(options) {
  if (model_ == nullptr) throw std::invalid_argument("TrajectoryOptimizer: the robot model is null");
  ValidateTrajectoryOptimizerOptions(options_);
  if (!(period >= 0.0) || !std::isfinite(period)) {
    throw std::invalid_argument("TrajectoryOptimizer: period " + FormatShort(period) +
                                " s must be finite and >= 0 (0: solve at initialization and on forced events only)");
  }
  DeclareAbstractInputPort("plan", systems::Value<FootstepPlan>(FootstepPlan()));
  DeclareAbstractInputPort("environment", systems::Value<std::vector<EnvironmentBox>>(std::vector<EnvironmentBox>()));
  DeclareAbstractInputPort("terrain", systems::Value<TerrainMap>(TerrainMap(Eigen::Vector2d::Zero(), 1, 1, 1.0)));
  trajectory_state_ = DeclareAbstractState(systems::Value<WholeBodyTrajectory>(NotSolvedYet()));
  const int state = trajectory_state_;
  DeclareAbstractOutputPort(
      "trajectory", systems::Value<WholeBodyTrajectory>(NotSolvedYet()),
      [state](const systems::Context& c, systems::AbstractValue* v) { v->SetFrom(c.get_abstract_state_value(state)); },
      {abstract_state_ticket(state)});
  DeclareInitializationUnrestrictedUpdateEvent(&TrajectoryOptimizer::Solve);
  DeclareForcedUnrestrictedUpdateEvent(&TrajectoryOptimizer::Solve);
  if (period > 0.0) DeclarePeriodicUnrestrictedUpdateEvent(period, period, &TrajectoryOptimizer::Solve);
}

void TrajectoryOptimizer::Solve(const systems::Context& context, systems::State* next) const {
  const auto& plan = get_plan_input_port().Eval<FootstepPlan>(context);
  const auto& environment = get_environment_input_port().Eval<std::vector<EnvironmentBox>>(context);
  const TerrainMap* terrain =
      get_terrain_input_port().HasValue(context) ? &get_terrain_input_port().Eval<TerrainMap>(context) : nullptr;
  next->get_mutable_abstract_state<WholeBodyTrajectory>(trajectory_state_) =
      OptimizeWholeBodyTrajectory(model_, plan, environment, options_, terrain);
}

}  // namespace cairn::planning
