#include "cairn/optimization/solvers/nlopt_solver.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstring>
#include <exception>
#include <limits>
#include <stdexcept>

#include <nlopt.hpp>

#include "cairn/common/number_text.h"
#include "cairn/common/text_suggestions.h"
#include "cairn/optimization/program_assembly.h"

namespace cairn::optimization {

namespace {

constexpr double kUnboundedObjective = -1e20;
const char* const kOptionNames[] = {"maxeval",  "maxtime", "xtol_rel",       "xtol_abs",   "ftol_rel",
                                    "ftol_abs", "stopval", "constraint_tol", "population", "seed"};

std::string StripPrefix(const std::string& name) {
  const std::size_t underscore = name.find('_');
  if (underscore == std::string::npos) return name;
  const std::string prefix = name.substr(0, underscore);
  if (prefix == "GN" || prefix == "GD" || prefix == "LN" || prefix == "LD" || prefix == "G") {
    return name.substr(underscore + 1);
  }
  return name;
}

bool IsGlobal(const std::string& name) {
  return name.rfind("GN_", 0) == 0 || name.rfind("GD_", 0) == 0 || name.rfind("G_", 0) == 0;
}

// Algorithms that draw random numbers; NLopt seeds them from the clock unless told otherwise.
bool IsStochastic(const std::string& name) {
  static const char* const kNames[] = {"GN_CRS2_LM", "GN_MLSL",     "GD_MLSL", "GN_MLSL_LDS", "GD_MLSL_LDS",
                                       "G_MLSL",     "G_MLSL_LDS", "GN_ISRES", "GN_ESCH"};
  return std::find(std::begin(kNames), std::end(kNames), name) != std::end(kNames);
}

bool SupportsEqualities(const std::string& name) {
  static const char* const kNames[] = {"LD_SLSQP",  "LN_COBYLA", "GN_ISRES",     "AUGLAG",      "AUGLAG_EQ",
                                       "LN_AUGLAG", "LD_AUGLAG", "LN_AUGLAG_EQ", "LD_AUGLAG_EQ"};
  return std::find(std::begin(kNames), std::end(kNames), name) != std::end(kNames);
}

bool SupportsInequalities(const std::string& name) {
  static const char* const kNames[] = {"LD_MMA", "LD_CCSAQ", "GN_ORIG_DIRECT", "GN_ORIG_DIRECT_L", "GN_AGS"};
  return SupportsEqualities(name) || std::find(std::begin(kNames), std::end(kNames), name) != std::end(kNames);
}

// Resolves a user-facing algorithm name to NLopt's name and enum value.
std::pair<std::string, int> ResolveAlgorithm(const std::string& requested) {
  std::string name = requested;
  std::transform(name.begin(), name.end(), name.begin(), [](unsigned char c) { return std::toupper(c); });
  const std::vector<std::string> names = NloptSolver::AlgorithmNames();
  std::vector<std::size_t> matches;
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (names[i] == name) return {names[i], static_cast<int>(i)};
    if (StripPrefix(names[i]) == name) matches.push_back(i);
  }
  if (matches.size() == 1) return {names[matches[0]], static_cast<int>(matches[0])};
  if (matches.size() > 1) {
    std::vector<std::string> options;
    for (std::size_t i : matches) options.push_back(names[i]);
    throw std::invalid_argument("NloptSolver: algorithm '" + requested + "' is ambiguous; write one of " +
                                QuotedList(options) + ".");
  }
  const std::vector<std::string> closest = ClosestNames(name, names);
  throw std::invalid_argument("NloptSolver: unknown NLopt algorithm '" + requested + "'" +
                              (closest.empty() ? "" : " (did you mean " + QuotedList(closest) + "?)") +
                              "; valid names are " + QuotedList(names) +
                              ", or the part after the prefix when unambiguous (e.g. 'SLSQP').");
}

// The state NLopt's callbacks share: the assembly, the mapping of stacked rows to NLopt's constraint slots,
// and a cache so that the equality and inequality callbacks evaluate the constraints once per point.
class NloptProblem {
 public:
  explicit NloptProblem(ProgramAssembly* assembly) : assembly_(assembly), n_(assembly->num_vars()) {
    const int rows = assembly->num_constraints();
    std::vector<std::array<int, 2>> row_slots(static_cast<std::size_t>(rows), {-1, -1});
    std::vector<char> row_is_equality(static_cast<std::size_t>(rows), 0);
    for (int r = 0; r < rows; ++r) {
      const double lb = assembly->constraint_lower_bounds()[r];
      const double ub = assembly->constraint_upper_bounds()[r];
      auto& slots = row_slots[static_cast<std::size_t>(r)];
      if (lb == ub) {
        slots[0] = static_cast<int>(equalities_.size());
        row_is_equality[static_cast<std::size_t>(r)] = 1;
        equalities_.push_back({r, 1.0, lb});
        continue;
      }
      if (std::isfinite(ub)) {
        slots[0] = static_cast<int>(inequalities_.size());
        inequalities_.push_back({r, 1.0, ub});
      }
      if (std::isfinite(lb)) {
        slots[1] = static_cast<int>(inequalities_.size());
        inequalities_.push_back({r, -1.0, lb});
      }
    }
    // Where each Jacobian value lands in NLopt's dense row-major gradients, worked out once.
    const std::vector<int>& jac_rows = assembly->jacobian_rows();
    const std::vector<int>& jac_cols = assembly->jacobian_cols();
    for (std::size_t k = 0; k < jac_rows.size(); ++k) {
      const std::size_t row = static_cast<std::size_t>(jac_rows[k]);
      const bool equality = row_is_equality[row] != 0;
      std::vector<Scatter>& scatter = equality ? equality_scatter_ : inequality_scatter_;
      const std::vector<Slot>& slots = equality ? equalities_ : inequalities_;
      for (int slot : row_slots[row]) {
        if (slot < 0) continue;
        scatter.push_back({static_cast<int>(k), slot * n_ + jac_cols[k], slots[static_cast<std::size_t>(slot)].sign});
      }
    }
    // One buffer for the constraint values, the Jacobian values and the cached point.
    buffer_.resize(static_cast<std::size_t>(rows + assembly->jacobian_nonzeros() + n_));
    g_ = buffer_.data();
    jacobian_values_ = g_ + rows;
    cached_x_ = jacobian_values_ + assembly->jacobian_nonzeros();
    std::fill(cached_x_, cached_x_ + n_, std::numeric_limits<double>::quiet_NaN());
  }

  int num_equalities() const { return static_cast<int>(equalities_.size()); }
  int num_inequalities() const { return static_cast<int>(inequalities_.size()); }
  std::exception_ptr error() const { return error_; }

  static double Objective(unsigned, const double* x, double* grad, void* data) {
    auto* self = static_cast<NloptProblem*>(data);
    try {
      return grad != nullptr ? self->assembly_->EvalCostAndGradient(x, grad) : self->assembly_->EvalCost(x);
    } catch (...) {
      self->error_ = std::current_exception();
      throw nlopt::forced_stop();
    }
  }

  static void Inequalities(unsigned m, double* result, unsigned, const double* x, double* grad, void* data) {
    auto* self = static_cast<NloptProblem*>(data);
    self->Fill(self->inequalities_, self->inequality_scatter_, m, result, x, grad);
  }

  static void Equalities(unsigned m, double* result, unsigned, const double* x, double* grad, void* data) {
    auto* self = static_cast<NloptProblem*>(data);
    self->Fill(self->equalities_, self->equality_scatter_, m, result, x, grad);
  }

 private:
  struct Slot {
    int row;
    double sign;  // +1: g - bound (<= 0 or == 0); -1: bound - g <= 0
    double bound;
  };
  struct Scatter {
    int value;  // index into the Jacobian values
    int dense;  // index into NLopt's m x n gradient
    double sign;
  };

  void Fill(const std::vector<Slot>& slots, const std::vector<Scatter>& scatter, unsigned m, double* result,
            const double* x, double* grad) {
    try {
      // NLopt asks for equalities and inequalities separately at the same point; evaluate the program once.
      if (std::memcmp(x, cached_x_, sizeof(double) * static_cast<std::size_t>(n_)) != 0) {
        std::copy(x, x + n_, cached_x_);
        have_values_ = have_jacobian_ = false;
      }
      if (grad != nullptr && !have_jacobian_) {
        assembly_->EvalConstraintsAndJacobian(x, g_, jacobian_values_);
        have_values_ = have_jacobian_ = true;
      } else if (!have_values_) {
        assembly_->EvalConstraints(x, g_);
        have_values_ = true;
      }
      for (unsigned i = 0; i < m; ++i) result[i] = slots[i].sign * (g_[slots[i].row] - slots[i].bound);
      if (grad == nullptr) return;
      std::fill(grad, grad + static_cast<std::size_t>(m) * static_cast<std::size_t>(n_), 0.0);
      for (const Scatter& e : scatter) grad[e.dense] += e.sign * jacobian_values_[e.value];
    } catch (...) {
      error_ = std::current_exception();
      throw nlopt::forced_stop();
    }
  }

  ProgramAssembly* assembly_;
  int n_;
  std::vector<Slot> equalities_;
  std::vector<Slot> inequalities_;
  std::vector<Scatter> equality_scatter_;
  std::vector<Scatter> inequality_scatter_;
  std::vector<double> buffer_;
  double* g_{nullptr};
  double* jacobian_values_{nullptr};
  double* cached_x_{nullptr};
  bool have_values_{false};
  bool have_jacobian_{false};
  std::exception_ptr error_;
};

struct StageSettings {
  int maxeval{0};
  double maxtime{0.0};
  double xtol_rel{0.0};
  double xtol_abs{0.0};
  double ftol_rel{0.0};
  double ftol_abs{0.0};
  double stopval{kUnboundedObjective};
  bool user_stopval{false};
  double constraint_tol{1e-8};
  int population{0};
  int seed{1};
};

double AsNumber(const std::string& option, const SolverOptions::Value& value) {
  if (const double* d = std::get_if<double>(&value)) return *d;
  if (const int* i = std::get_if<int>(&value)) return *i;
  throw std::invalid_argument("NloptSolver: option '" + option + "' is a number but was given " +
                              SolverOptions::ToString(value) + "; pass a number.");
}

int AsInteger(const std::string& option, const SolverOptions::Value& value) {
  if (const int* i = std::get_if<int>(&value)) return *i;
  throw std::invalid_argument("NloptSolver: option '" + option + "' is an integer but was given " +
                              SolverOptions::ToString(value) + "; pass an integer.");
}

// Each option's range, so that a value NLopt would read differently (a maxeval <= 0 as no limit, a negative
// seed wrapped to a huge unsigned, a negative tolerance as none) is an error rather than a surprise.
int AtLeast(const std::string& option, int value, int lowest, const char* why) {
  if (value < lowest) {
    throw std::invalid_argument("NloptSolver: option '" + option + "' = " + std::to_string(value) + " must be >= " +
                                std::to_string(lowest) + " (" + why + ").");
  }
  return value;
}

double Tolerance(const std::string& option, double value) {
  if (!(value >= 0.0) || !std::isfinite(value)) {
    throw std::invalid_argument("NloptSolver: option '" + option + "' = " + FormatShort(value) +
                                " must be finite and >= 0" +
                                (option == "constraint_tol" ? "." : " (0 turns the criterion off)."));
  }
  return value;
}

void Apply(const std::string& name, const SolverOptions::Value& value, StageSettings* s) {
  if (name == "maxeval") {
    s->maxeval = AtLeast(name, AsInteger(name, value), 1,
                         "NLopt reads 0 or less as no limit, and a global stage never stops without one");
  } else if (name == "population") {
    s->population = AtLeast(name, AsInteger(name, value), 0, "0 lets NLopt choose");
  } else if (name == "seed") {
    s->seed = AtLeast(name, AsInteger(name, value), 0, "NLopt's seed is unsigned");
  } else if (name == "maxtime") {
    s->maxtime = AsNumber(name, value);
    if (!(s->maxtime > 0.0)) {
      throw std::invalid_argument("NloptSolver: option 'maxtime' = " + FormatShort(s->maxtime) +
                                  " must be > 0 seconds (NLopt reads 0 or less as no limit; leave it out for none).");
    }
  } else if (name == "xtol_rel") {
    s->xtol_rel = Tolerance(name, AsNumber(name, value));
  } else if (name == "xtol_abs") {
    s->xtol_abs = Tolerance(name, AsNumber(name, value));
  } else if (name == "ftol_rel") {
    s->ftol_rel = Tolerance(name, AsNumber(name, value));
  } else if (name == "ftol_abs") {
    s->ftol_abs = Tolerance(name, AsNumber(name, value));
  } else if (name == "stopval") {
    s->stopval = AsNumber(name, value);
    if (std::isnan(s->stopval)) throw std::invalid_argument("NloptSolver: option 'stopval' is NaN; give a number.");
    s->user_stopval = true;
  } else if (name == "constraint_tol") {
    s->constraint_tol = Tolerance(name, AsNumber(name, value));
  } else {
    const std::vector<std::string> valid(std::begin(kOptionNames), std::end(kOptionNames));
    const std::vector<std::string> closest = ClosestNames(name, valid, 1);
    throw std::invalid_argument("NloptSolver: unknown option '" + name + "'" +
                                (closest.empty() ? "" : " (did you mean '" + closest[0] + "'?)") +
                                "; valid options are " + QuotedList(valid) +
                                ", optionally prefixed by a stage as in 'LD_SLSQP.maxeval'.");
  }
}

StageSettings SettingsFor(const std::string& stage, bool global, const std::vector<std::string>& stages,
                          const SolverOptions::OptionMap& options) {
  StageSettings s;
  if (global) {
    s.maxeval = 2000;
  } else {
    // SLSQP stops falsely early on HS100 with ftol_rel >= 1e-12 (its line search then reports a tiny change).
    s.xtol_rel = 1e-10;
    s.ftol_rel = 1e-14;
    s.maxeval = 100000;
  }
  // Unprefixed options first, then the stage's own, so "STAGE.name" wins.
  for (const auto& [name, value] : options) {
    if (name.find('.') == std::string::npos) Apply(name, value, &s);
  }
  for (const auto& [name, value] : options) {
    const std::size_t dot = name.find('.');
    if (dot == std::string::npos) continue;
    const std::string prefix = name.substr(0, dot);
    std::string resolved;
    try {
      resolved = ResolveAlgorithm(prefix).first;
    } catch (const std::invalid_argument&) {
      resolved.clear();
    }
    if (std::find(stages.begin(), stages.end(), resolved) == stages.end()) {
      throw std::invalid_argument("NloptSolver: option '" + name + "' names stage '" + prefix +
                                  "', which is not a stage of this solver; stages are " + QuotedList(stages) + ".");
    }
    if (resolved == stage) Apply(name.substr(dot + 1), value, &s);
  }
  return s;
}

}  // namespace

std::vector<std::string> NloptSolver::AlgorithmNames() {
  std::vector<std::string> names;
  for (int i = 0; i < NLOPT_NUM_ALGORITHMS; ++i) {
    names.emplace_back(nlopt_algorithm_to_string(static_cast<nlopt_algorithm>(i)));
  }
  return names;
}

NloptSolver::ParsedStages NloptSolver::Parse(const std::string& algorithms) {
  if (algorithms.empty()) {
    throw std::invalid_argument("NloptSolver: no algorithm given; pass e.g. 'SLSQP' or 'ORIG_DIRECT+SLSQP'.");
  }
  ParsedStages parsed;
  parsed.name = "nlopt:";
  std::size_t start = 0;
  while (true) {
    const std::size_t plus = algorithms.find('+', start);
    const std::string part = algorithms.substr(start, plus == std::string::npos ? std::string::npos : plus - start);
    const auto [canonical, value] = ResolveAlgorithm(part);
    parsed.stages.push_back(canonical);
    parsed.algorithms.push_back(value);
    parsed.flags.push_back(static_cast<unsigned char>((IsGlobal(canonical) ? kGlobal : 0) |
                                                      (IsStochastic(canonical) ? kStochastic : 0) |
                                                      (SupportsEqualities(canonical) ? kEqualities : 0) |
                                                      (SupportsInequalities(canonical) ? kInequalities : 0)));
    parsed.name += (parsed.stages.size() > 1 ? "+" : "") + canonical;
    if (plus == std::string::npos) break;
    start = plus + 1;
  }
  return parsed;
}

NloptSolver::NloptSolver(const std::string& algorithms) : NloptSolver(Parse(algorithms)) {}

NloptSolver::NloptSolver(ParsedStages parsed)
    : Solver(parsed.name, "nlopt"),
      stages_(std::move(parsed.stages)),
      algorithms_(std::move(parsed.algorithms)),
      flags_(std::move(parsed.flags)) {}

std::string NloptSolver::DoCheckSupport(const MathematicalProgram& prog) const {
  if (prog.num_vars() == 0) {
    return "NloptSolver: the program has no decision variables; add some with NewContinuousVariables.";
  }
  // Labels are built only for the message: this check runs on every solve of tiny problems.
  const Binding<Constraint>* equality_row = nullptr;
  const Binding<Constraint>* inequality_row = nullptr;
  for (const auto& binding : prog.constraints()) {
    const Constraint& c = *binding.evaluator();
    for (int r = 0; r < c.num_outputs(); ++r) {
      if (c.lower_bound()[r] == c.upper_bound()[r]) {
        if (equality_row == nullptr) equality_row = &binding;
      } else if (std::isfinite(c.lower_bound()[r]) || std::isfinite(c.upper_bound()[r])) {
        if (inequality_row == nullptr) inequality_row = &binding;
      }
    }
  }
  for (std::size_t k = 0; k < stages_.size(); ++k) {
    const std::string& stage = stages_[k];
    if (equality_row != nullptr && !(flags_[k] & kEqualities)) {
      return "NloptSolver: " + stage + " cannot handle equality constraints such as '" + equality_row->ToString() +
             "'; use SLSQP, COBYLA, ISRES or AUGLAG for programs with equalities.";
    }
    if (inequality_row != nullptr && !(flags_[k] & kInequalities)) {
      return "NloptSolver: " + stage + " cannot handle nonlinear inequality constraints such as '" +
             inequality_row->ToString() + "'; use SLSQP, COBYLA, MMA, CCSAQ, ISRES, ORIG_DIRECT or AUGLAG.";
    }
    if (flags_[k] & kGlobal) {
      const Eigen::VectorXd lower = prog.variable_lower_bounds();
      const Eigen::VectorXd upper = prog.variable_upper_bounds();
      for (int i = 0; i < prog.num_vars(); ++i) {
        if (!std::isfinite(lower[i]) || !std::isfinite(upper[i])) {
          return "NloptSolver: the global algorithm " + stage + " needs finite bounds on every variable, but '" +
                 prog.VariableName(i) + "' has bounds [" + std::to_string(lower[i]) + ", " +
                 std::to_string(upper[i]) + "]; add them with AddBoundingBoxConstraint.";
        }
      }
    }
  }
  return "";
}

SolverResult NloptSolver::DoSolve(const MathematicalProgram& prog, const Eigen::VectorXd& initial_guess,
                                  const SolverOptions::OptionMap& options) const {
  // Settings are validated before any work so that a typo fails fast.
  std::vector<StageSettings> settings;
  for (std::size_t k = 0; k < stages_.size(); ++k) {
    settings.push_back(SettingsFor(stages_[k], (flags_[k] & kGlobal) != 0, stages_, options));
  }

  ProgramAssembly assembly(prog);
  NloptProblem problem(&assembly);
  const int n = prog.num_vars();
  const Eigen::VectorXd& lower_bounds = assembly.variable_lower_bounds();
  const Eigen::VectorXd& upper_bounds = assembly.variable_upper_bounds();
  const std::vector<double> lower(lower_bounds.data(), lower_bounds.data() + n);
  const std::vector<double> upper(upper_bounds.data(), upper_bounds.data() + n);
  // NLopt refuses starting points outside the bounds; every solver starts from the projected guess.
  std::vector<double> x(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) x[static_cast<std::size_t>(i)] = std::clamp(initial_guess[i], lower[i], upper[i]);

  SolverResult result;
  result.evaluations = 0;
  nlopt::result last = nlopt::FAILURE;
  std::string failure;
  bool unbounded = false;
  for (std::size_t k = 0; k < stages_.size(); ++k) {
    const StageSettings& s = settings[k];
    nlopt::opt opt(static_cast<nlopt::algorithm>(algorithms_[k]), static_cast<unsigned>(n));
    opt.set_lower_bounds(lower);
    opt.set_upper_bounds(upper);
    opt.set_min_objective(&NloptProblem::Objective, &problem);
    if (problem.num_inequalities() > 0) {
      opt.add_inequality_mconstraint(
          &NloptProblem::Inequalities, &problem,
          std::vector<double>(static_cast<std::size_t>(problem.num_inequalities()), s.constraint_tol));
    }
    if (problem.num_equalities() > 0) {
      opt.add_equality_mconstraint(
          &NloptProblem::Equalities, &problem,
          std::vector<double>(static_cast<std::size_t>(problem.num_equalities()), s.constraint_tol));
    }
    if (s.maxeval > 0) opt.set_maxeval(s.maxeval);
    if (s.maxtime > 0) opt.set_maxtime(s.maxtime);
    if (s.xtol_rel > 0) opt.set_xtol_rel(s.xtol_rel);
    if (s.xtol_abs > 0) opt.set_xtol_abs(s.xtol_abs);
    if (s.ftol_rel > 0) opt.set_ftol_rel(s.ftol_rel);
    if (s.ftol_abs > 0) opt.set_ftol_abs(s.ftol_abs);
    if (s.population > 0) opt.set_population(static_cast<unsigned>(s.population));
    opt.set_stopval(s.stopval);
    if (flags_[k] & kStochastic) nlopt::srand(static_cast<unsigned long>(s.seed));
    double f = 0.0;
    failure.clear();
    try {
      last = opt.optimize(x, f);
    } catch (const nlopt::roundoff_limited&) {
      last = nlopt::ROUNDOFF_LIMITED;
      failure = "round-off limited progress";
    } catch (const nlopt::forced_stop&) {
      if (problem.error()) std::rethrow_exception(problem.error());
      last = nlopt::FORCED_STOP;
      failure = "forced stop";
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument("NloptSolver: NLopt rejected the " + stages_[k] + " stage (" + e.what() +
                                  "); check its options and the program's bounds.");
    } catch (const std::bad_alloc&) {
      throw;
    } catch (const std::runtime_error& e) {
      last = nlopt::FAILURE;
      failure = e.what();
    }
    result.evaluations += opt.get_numevals();
    unbounded = (!s.user_stopval && last == nlopt::STOPVAL_REACHED) || f < kUnboundedObjective ||
                !std::all_of(x.begin(), x.end(), [](double v) { return std::isfinite(v); });
    result.message += (k > 0 ? "; " : "") + stages_[k] + ": " +
                      (failure.empty() ? std::string(nlopt_result_to_string(static_cast<nlopt_result>(last)))
                                       : failure);
    if (unbounded) break;
  }

  result.x = Eigen::Map<const Eigen::VectorXd>(x.data(), n);
  const double tolerance = settings.back().constraint_tol;
  if (unbounded) {
    result.status = SolutionStatus::kUnbounded;
    result.objective = -std::numeric_limits<double>::infinity();
    result.constraint_violation = std::numeric_limits<double>::quiet_NaN();
    return result;
  }
  result.objective = assembly.EvalCost(x.data());
  result.constraint_violation = assembly.ConstraintViolation(x.data());
  const bool feasible = result.constraint_violation <= tolerance;
  switch (last) {
    case nlopt::SUCCESS:
    case nlopt::STOPVAL_REACHED:
    case nlopt::FTOL_REACHED:
    case nlopt::XTOL_REACHED:
      result.status = feasible ? SolutionStatus::kSolved : SolutionStatus::kInfeasible;
      break;
    case nlopt::MAXEVAL_REACHED:
      result.status = SolutionStatus::kIterationLimit;
      break;
    case nlopt::MAXTIME_REACHED:
      result.status = SolutionStatus::kTimeLimit;
      break;
    case nlopt::ROUNDOFF_LIMITED:
      // NLopt: "the optimization still typically returns a useful result"; SLSQP ends this way when the
      // tolerances ask for more than double precision gives. Only a feasible point counts.
      result.status = feasible ? SolutionStatus::kSolved : SolutionStatus::kInfeasible;
      break;
    default:
      result.status = feasible ? SolutionStatus::kNumericalFailure : SolutionStatus::kInfeasible;
      break;
  }
  if (!feasible) result.message += "; largest violation " + assembly.DescribeWorstViolation(x.data());
  return result;
}

}  // namespace cairn::optimization
