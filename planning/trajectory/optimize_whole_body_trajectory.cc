#include <cairn/planning/trajectory/optimize_whole_body_trajectory.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

#include <cairn/common/number_text.h>
#include <cairn/multibody/center_of_mass.h>
#include <cairn/multibody/data.h>
#include <cairn/optimization/solvers/make_solver.h>
#include <cairn/optimization/solvers/solver.h>
#include <cairn/planning/trajectory/configuration_chart.h>
#include <cairn/planning/trajectory/trajectory_problem.h>
#include <cairn/planning/trajectory/waypoint_spec.h>

namespace cairn::planning {

namespace {
// Rows violated by more than this are reported; a solve is a success only if none is.
constexpr double kReportThreshold = 1e-6;
constexpr std::size_t kMaxReported = 5;

optimization::SolverOptions MakeSolverOptions(const optimization::Solver& solver,
                                              const TrajectoryOptimizerOptions& options) {
  optimization::SolverOptions out;
  if (solver.options_key() == "ipopt") {
    out.Set("ipopt", "max_iter", options.max_iterations);
    out.Set("ipopt", "tol", options.tolerance);
    out.Set("ipopt", "constr_viol_tol", 0.1 * options.tolerance);
    out.Set("ipopt", "acceptable_iter", 0);  // never stop at the merely "acceptable" level
    if (options.hessian == "gauss-newton") {
      out.Set("ipopt", "hessian_approximation", "exact");
      out.Set("ipopt", "least_squares_hessian", "gauss-newton");
    } else {
      out.Set("ipopt", "hessian_approximation", options.hessian);
    }
  } else if (solver.options_key() == "nlopt") {
    out.Set("nlopt", "maxeval", 50 * options.max_iterations);
    out.Set("nlopt", "constraint_tol", 0.1 * options.tolerance);
  }
  return out;
}
// The options with the level ground lowered by the deepest reach of a tilted sole target's corner below its own
// centre: a sole laid on a slope is not pushed out of a floor that cuts into its heel. Level soles leave it as it
// is (the walks on level and perceived ground solve the same problem as before soles were tilted).
TrajectoryOptimizerOptions WithGroundUnderTheSoles(const TrajectoryOptimizerOptions& options,
                                                   const std::vector<WaypointSpec>& specs) {
  TrajectoryOptimizerOptions out = options;
  double reach = 0.0;
  for (const WaypointSpec& spec : specs) {
    for (const WaypointContact& contact : spec.contacts) {
      for (const double sx : {-0.5, 0.5}) {
        for (const double sy : {-0.5, 0.5}) {
          const Eigen::Vector3d corner_S(sx * options.sole_length, sy * options.sole_width, 0.0);
          reach = std::min(reach, (contact.X_WF.rotation() * corner_S).z());
        }
      }
    }
  }
  out.ground_height += reach;  // NaN stays NaN
  return out;
}
}  // namespace

WholeBodyTrajectory OptimizeWholeBodyTrajectory(std::shared_ptr<const multibody::Model> model, const FootstepPlan& plan,
                                                const std::vector<EnvironmentBox>& environment,
                                                const TrajectoryOptimizerOptions& options, const TerrainMap* terrain) {
  if (model == nullptr) throw std::invalid_argument("OptimizeWholeBodyTrajectory: the robot model is null");
  ValidateTrajectoryOptimizerOptions(options);
  const std::unique_ptr<optimization::Solver> solver = optimization::MakeSolver(options.solver);
  WholeBodyTrajectory out;
  out.report.solver = solver->name();
  if (!plan.found) {
    out.report.status = "no footstep plan";
    out.report.message = "no footstep plan to optimise: " + plan.reason;
    return out;
  }
  const std::vector<WaypointSpec> specs = MakeWaypointSpecs(plan, options, terrain);
  // The collision terms keep their own copy of the ground (evaluators are shared objects).
  const std::shared_ptr<const TerrainMap> ground = terrain != nullptr && options.ground_follows_terrain
                                                       ? std::make_shared<const TerrainMap>(*terrain)
                                                       : nullptr;
  const TrajectoryOptimizerOptions problem_options = WithGroundUnderTheSoles(options, specs);
  const int num_stances = static_cast<int>(plan.steps.size()) + 1;
  const int window = options.window_stances == 0 ? num_stances : std::min(options.window_stances, num_stances);
  const auto total = static_cast<int>(specs.size());

  std::optional<TrajectoryProblem::FixedWaypoint> previous;
  const ConfigurationChart chart(*model);
  std::vector<Eigen::VectorXd> carried;  // the previous window's solution past the waypoints it kept
  bool success = true;
  std::vector<RowViolation> worst;
  for (int stance = 0; stance < num_stances; ++stance) {
    const int first = 2 * stance;
    const int last = std::min(2 * (stance + window) - 1, total) ;  // one past the window's last waypoint
    const bool final_window = last >= total;
    std::vector<WaypointSpec> window_specs(specs.begin() + first, specs.begin() + last);
    const TrajectoryProblem problem(model, window_specs, environment, problem_options, previous, ground);
    if (out.coordinate_names.empty()) out.coordinate_names = problem.coordinate_names();
    // Warm start: the previous window's solution where the windows overlap, inverse kinematics beyond.
    std::vector<Eigen::VectorXd> start_q = problem.WarmStart();
    for (std::size_t i = 0; i < carried.size() && i < start_q.size(); ++i) start_q[i] = carried[i];
    if (chart.has_floating_base()) {
      for (std::size_t i = 0; i < start_q.size(); ++i) {
        const Eigen::VectorXd& before = i > 0 ? start_q[i - 1] : (previous ? previous->q : start_q[i]);
        if (start_q[i].segment<4>(3).dot(before.segment<4>(3)) < 0.0) start_q[i].segment<4>(3) *= -1.0;
      }
    }
    const Eigen::VectorXd guess = problem.DecisionVector(start_q);
    const auto start = std::chrono::steady_clock::now();
    const optimization::SolverResult result = solver->Solve(problem.program(), guess, MakeSolverOptions(*solver, options));
    out.report.seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    out.report.iterations += std::max(0, result.iterations);
    out.report.objective += result.objective;
    ++out.report.windows;
    if (problem.program().num_vars() > out.report.num_variables) {
      out.report.num_variables = problem.program().num_vars();
      int rows = 0, nonzeros = 0;
      for (const auto& c : problem.program().constraints()) {
        rows += c.evaluator()->num_outputs();
        nonzeros += c.evaluator()->jacobian_nonzeros();
      }
      out.report.num_constraints = rows;
      out.report.jacobian_nonzeros = nonzeros;
      int hessian = 0;
      const auto count = [&hessian](const auto& terms) {
        for (const auto& t : terms) {
          if (t.evaluator()->has_hessian()) hessian += static_cast<int>(t.evaluator()->hessian_pattern().size());
        }
      };
      count(problem.program().costs());
      count(problem.program().least_squares_costs());
      count(problem.program().constraints());
      out.report.hessian_nonzeros = hessian;
    }
    if (out.report.status.empty() || !result.is_success()) out.report.status = optimization::to_string(result.status);
    const std::vector<RowViolation> violations = problem.Violations(result.x, kReportThreshold);
    if (!result.is_success() || !violations.empty()) success = false;
    worst.insert(worst.end(), violations.begin(), violations.end());
    for (const RowViolation& v : violations) out.report.max_violation = std::max(out.report.max_violation, v.amount);

    std::string sample_pair;
    const double sample_clearance = problem.MinimumSampleClearance(result.x, &sample_pair);
    if (sample_clearance < out.report.min_sample_clearance) {
      out.report.min_sample_clearance = sample_clearance;
      out.report.min_sample_pair = sample_pair;
    }
    const int keep = final_window ? problem.num_waypoints() : std::min(2, problem.num_waypoints());
    for (int i = 0; i < keep; ++i) {
      WholeBodyWaypoint w;
      const WaypointSpec& spec = problem.spec(i);
      w.time = spec.time;
      w.stance = spec.stance;
      w.single_support = spec.single_support;
      w.label = spec.label;
      w.q = problem.WaypointConfiguration(result.x, i);
      for (const WaypointContact& c : spec.contacts) w.contacts.push_back(c.frame);
      multibody::Data data(*model);
      w.com = multibody::CenterOfMass(*model, data, w.q);
      w.min_clearance = problem.MinimumClearance(result.x, i);
      w.torque_cost = problem.TorqueCost(result.x, i);
      out.report.torque_cost += w.torque_cost;
      out.waypoints.push_back(std::move(w));
    }
    if (final_window) break;
    carried.clear();
    for (int i = keep; i < problem.num_waypoints(); ++i) carried.push_back(problem.WaypointConfiguration(result.x, i));
    previous = TrajectoryProblem::FixedWaypoint{problem.spec(keep - 1), problem.WaypointConfiguration(result.x, keep - 1)};
  }
  out.report.hessian = solver->options_key() == "ipopt" ? options.hessian : "solver's own";
  std::stable_sort(worst.begin(), worst.end(),
                   [](const RowViolation& a, const RowViolation& b) { return a.amount > b.amount; });
  for (std::size_t i = 0; i < worst.size() && i < kMaxReported; ++i) out.report.violations.push_back(worst[i].ToString());
  out.report.success = success;
  out.found = success;
  out.report.message = out.report.status;
  if (!out.report.violations.empty()) {
    out.report.message += "; most violated: " + out.report.violations.front();
    for (std::size_t i = 1; i < out.report.violations.size(); ++i) out.report.message += "; " + out.report.violations[i];
  }
  return out;
}

}  // namespace cairn::planning
