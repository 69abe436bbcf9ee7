#include "cairn/common/number_text.h"
#include "cairn/planning/locomotion/transition_optimizer.h"

#include <array>
#include <cmath>
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "cairn/optimization/function_evaluator.h"
#include "cairn/optimization/mathematical_program.h"
#include "cairn/optimization/solvers/nlopt_solver.h"
#include "cairn/optimization/solvers/solver_options.h"
#include "cairn/planning/locomotion/step_evaluator.h"

namespace cairn::planning {
namespace {

// Constraint rows are held this far inside their limits, so that the solvers' points pass StepEvaluator's
// exact feasibility test (friction rows in units of m g, leg rows in metres and radians).
constexpr double kRowMargin = 1e-7;
constexpr double kRcofSlack = 1e-9;

// Evaluates steps for the solvers, remembering the last few points: NLopt asks for the objective and the
// constraints (and their finite-difference stencils) at the same points separately.
//
// The solvers see scaled quantities, because SLSQP starts from an identity Hessian and its steps are only
// sensible when variables, cost and rows are all of order one: the decision variables are u in [0, 1]^3
// spanning the parameter box, the cost is divided by `cost_scale`, friction rows are in units of the weight
// m g, and leg-length rows in units of the knee range's length span.
class StepProblem {
 public:
  StepProblem(const WalkingModel& model, const StepDisplacement& d, double mu, WalkingObjective objective,
              const WalkingPatternOptions& options)
      : evaluator_(model, options), d_(d), mu_(mu), objective_(objective), model_(model) {
    rows_ = 4 * evaluator_.num_contact_samples();
    const StepParameters& lo = model.parameter_lower();
    const StepParameters& hi = model.parameter_upper();
    lower_ << lo.t_ds, lo.t_sw, lo.com_height;
    span_ << hi.t_ds - lo.t_ds, hi.t_sw - lo.t_sw, hi.com_height - lo.com_height;
  }

  int num_rows() const { return rows_; }
  void set_cost_scale(double scale) { cost_scale_ = scale; }

  StepParameters ToParameters(const Eigen::Ref<const Eigen::VectorXd>& u) const {
    const Eigen::Vector3d x = lower_ + span_.cwiseProduct(u);
    return StepParameters{x[0], x[1], x[2]};
  }
  Eigen::Vector3d ToUnit(const StepParameters& p) const {
    Eigen::Vector3d u = (Eigen::Vector3d(p.t_ds, p.t_sw, p.com_height) - lower_).cwiseQuotient(span_);
    for (int i = 0; i < 3; ++i) {
      if (span_[i] == 0.0) u[i] = 0.0;  // a fixed parameter
    }
    return u;
  }

  double Cost(const Eigen::Ref<const Eigen::VectorXd>& u) { return Lookup(u).cost / cost_scale_; }

  void Rows(const Eigen::Ref<const Eigen::VectorXd>& u, Eigen::Ref<Eigen::VectorXd> y) { y = Lookup(u).rows; }

  const StepEvaluation& Evaluate(const StepParameters& p) { return evaluator_.Evaluate(d_, p); }

 private:
  struct Entry {
    std::array<double, 3> x{};
    double cost{0.0};
    Eigen::VectorXd rows;
    bool used{false};
  };

  const Entry& Lookup(const Eigen::Ref<const Eigen::VectorXd>& x) {
    for (const Entry& entry : cache_) {
      if (entry.used && entry.x[0] == x[0] && entry.x[1] == x[1] && entry.x[2] == x[2]) return entry;
    }
    Entry& entry = cache_[next_];
    next_ = (next_ + 1) % cache_.size();
    entry.used = true;
    entry.x = {x[0], x[1], x[2]};
    const StepEvaluation& e = evaluator_.Evaluate(d_, ToParameters(x));
    entry.cost = ObjectiveValue(objective_, e);
    const int c = evaluator_.num_contact_samples();
    const double weight = model_.mass() * model_.gravity();
    const LegGeometry& leg = model_.leg();
    const double length_unit = leg.leg_length_max - leg.leg_length_min;
    entry.rows.resize(rows_);
    for (int i = 0; i < c; ++i) {
      entry.rows[i] = (e.tangential_force[i] - mu_ * e.normal_force[i]) / weight;
      entry.rows[c + i] = (e.leg_length[i] - leg.leg_length_max) / length_unit;
      entry.rows[2 * c + i] = (leg.leg_length_min - e.leg_length[i]) / length_unit;
      entry.rows[3 * c + i] = e.leg_posture_excess[i];
    }
    return entry;
  }

  StepEvaluator evaluator_;
  StepDisplacement d_;
  double mu_;
  WalkingObjective objective_;
  const WalkingModel& model_;
  int rows_{0};
  Eigen::Vector3d lower_, span_;
  double cost_scale_{1.0};
  std::array<Entry, 16> cache_;
  std::size_t next_{0};
};

void CheckFinite(double value, const char* name) {
  if (!std::isfinite(value)) {
    throw std::invalid_argument(std::string("OptimizeTransition: the displacement's ") + name +
                                " is not finite; pass a finite step displacement.");
  }
}

}  // namespace

TransitionCost OptimizeTransition(const WalkingModel& model, const StepDisplacement& d, double mu_allowed,
                                  WalkingObjective objective, const StepParameters* warm_start,
                                  const TransitionOptimizerOptions& options) {
  if (!(mu_allowed >= 0.0) || !std::isfinite(mu_allowed)) {
    throw std::invalid_argument("OptimizeTransition: mu_allowed is " + cairn::FormatShort(mu_allowed) +
                                "; it must be a finite friction coefficient >= 0 (0 means not walkable).");
  }
  CheckFinite(d.dx, "dx");
  CheckFinite(d.dy, "dy");
  CheckFinite(d.dz, "dz");
  CheckFinite(d.dtheta, "dtheta");
  if (options.direct_max_evaluations < 1 || options.slsqp_max_evaluations < 1) {
    throw std::invalid_argument("OptimizeTransition: the evaluation budgets must be >= 1 (got direct " +
                                cairn::FormatShort(options.direct_max_evaluations) + ", slsqp " +
                                cairn::FormatShort(options.slsqp_max_evaluations) + ").");
  }
  const StepParameters& lo = model.parameter_lower();
  const StepParameters& hi = model.parameter_upper();
  if (warm_start != nullptr) {
    const StepParameters& w = *warm_start;
    if (!(w.t_ds >= lo.t_ds && w.t_ds <= hi.t_ds && w.t_sw >= lo.t_sw && w.t_sw <= hi.t_sw &&
          w.com_height >= lo.com_height && w.com_height <= hi.com_height)) {
      throw std::invalid_argument("OptimizeTransition: the warm start (t_ds " + cairn::FormatShort(w.t_ds) + ", t_sw " +
                                  cairn::FormatShort(w.t_sw) + ", com_height " + cairn::FormatShort(w.com_height) +
                                  ") is outside the model's parameter bounds.");
    }
  }
  TransitionCost result;
  if (mu_allowed == 0.0 || !model.reach().Contains(d)) return result;
  if (d.dz != 0.0 && 2.0 * std::abs(d.dx) < model.foot_length()) return result;  // no periodic gait (kSolesOverlap)

  auto problem = std::make_shared<StepProblem>(model, d, mu_allowed, objective, options.pattern);
  optimization::MathematicalProgram prog;
  const optimization::DecisionVariables p = prog.NewContinuousVariables(3, "p");
  prog.AddBoundingBoxConstraint(0.0, 1.0, p);
  prog.AddCost(std::make_shared<optimization::FunctionEvaluator>(
                   "step_cost", 3, 1,
                   [problem](const Eigen::Ref<const Eigen::VectorXd>& x, Eigen::Ref<Eigen::VectorXd> y) {
                     y[0] = problem->Cost(x);
                   }),
               p);
  const int rows = problem->num_rows();
  prog.AddConstraint(std::make_shared<optimization::FunctionEvaluator>(
                         "step_feasibility", 3, rows,
                         [problem](const Eigen::Ref<const Eigen::VectorXd>& x, Eigen::Ref<Eigen::VectorXd> y) {
                           problem->Rows(x, y);
                         }),
                     Eigen::VectorXd::Constant(rows, -std::numeric_limits<double>::infinity()),
                     Eigen::VectorXd::Constant(rows, -kRowMargin), p);

  // Candidates: the warm start or DIRECT's point, then SLSQP's; keep the cheapest one that is feasible.
  std::vector<Eigen::Vector3d> candidates;
  Eigen::Vector3d start;
  if (warm_start != nullptr) {
    start = problem->ToUnit(*warm_start);
  } else {
    optimization::SolverOptions direct_options;
    direct_options.Set("nlopt", "maxeval", options.direct_max_evaluations);
    const optimization::NloptSolver direct("ORIG_DIRECT");
    const optimization::SolverResult global = direct.Solve(prog, Eigen::Vector3d::Zero(), direct_options);
    start = global.x;
  }
  candidates.push_back(start);
  // Scale the cost to order one at the start (any positive scale keeps the minimiser).
  const double start_cost = std::abs(problem->Cost(start));
  problem->set_cost_scale(start_cost > 1e-12 ? start_cost : 1.0);
  optimization::SolverOptions local_options;
  local_options.Set("nlopt", "maxeval", options.slsqp_max_evaluations);
  local_options.Set("nlopt", "xtol_rel", 1e-7);
  local_options.Set("nlopt", "ftol_rel", 1e-9);
  const optimization::NloptSolver slsqp("SLSQP");
  const optimization::SolverResult local = slsqp.Solve(prog, start, local_options);
  candidates.push_back(local.x);

  for (const Eigen::Vector3d& x : candidates) {
    if (!x.allFinite()) continue;
    const StepParameters candidate = problem->ToParameters(x.cwiseMax(0.0).cwiseMin(1.0));
    const StepEvaluation& e = problem->Evaluate(candidate);
    if (!e.feasible || !(e.rcof <= mu_allowed + kRcofSlack)) continue;
    const double cost = ObjectiveValue(objective, e);
    if (result.feasible && !(cost < result.cost)) continue;
    result.feasible = true;
    result.cost = cost;
    result.parameters = candidate;
    result.com_work = e.com_work;
    result.heat = e.heat;
    result.rcof = e.rcof;
    result.duration = e.duration;
  }
  return result;
}

}  // namespace cairn::planning
