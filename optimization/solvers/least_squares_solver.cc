#include "cairn/optimization/solvers/least_squares_solver.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

#include <Eigen/CholmodSupport>
#include <Eigen/SparseCore>

#include "cairn/common/number_text.h"
#include "cairn/common/text_suggestions.h"
#include "cairn/optimization/program_assembly.h"

namespace cairn::optimization {

namespace {

struct Settings {
  bool gauss_newton{false};
  int max_iterations{200};
  double gradient_tolerance{1e-10};
  double step_tolerance{1e-12};
  double function_tolerance{1e-14};
  double initial_damping{1e-4};
  double constraint_tol{1e-9};
  int max_outer_iterations{30};
};

double Number(const std::string& name, const SolverOptions::Value& value) {
  if (const double* d = std::get_if<double>(&value)) return *d;
  if (const int* i = std::get_if<int>(&value)) return *i;
  throw std::invalid_argument("LeastSquaresSolver: option '" + name + "' is a number but was given " +
                              SolverOptions::ToString(value) + "; pass a number.");
}

int Integer(const std::string& name, const SolverOptions::Value& value) {
  if (const int* i = std::get_if<int>(&value)) return *i;
  throw std::invalid_argument("LeastSquaresSolver: option '" + name + "' is an integer but was given " +
                              SolverOptions::ToString(value) + "; pass an integer.");
}

int AtLeastOne(const std::string& name, int value) {
  if (value < 1) {
    throw std::invalid_argument("LeastSquaresSolver: option '" + name + "' = " + std::to_string(value) +
                                " must be >= 1.");
  }
  return value;
}

double NonNegative(const std::string& name, double value, bool strict) {
  if ((strict ? !(value > 0.0) : !(value >= 0.0)) || !std::isfinite(value)) {
    throw std::invalid_argument("LeastSquaresSolver: option '" + name + "' = " + FormatShort(value) +
                                " must be finite and " + (strict ? "> 0." : ">= 0."));
  }
  return value;
}

Settings ParseOptions(const SolverOptions::OptionMap& options) {
  static const std::vector<std::string> kNames = {
      "algorithm",        "max_iterations",  "gradient_tolerance", "step_tolerance",
      "function_tolerance", "initial_damping", "constraint_tol",     "max_outer_iterations"};
  Settings s;
  for (const auto& [name, value] : options) {
    if (name == "algorithm") {
      const std::string* text = std::get_if<std::string>(&value);
      if (text == nullptr || (*text != "levenberg_marquardt" && *text != "gauss_newton")) {
        throw std::invalid_argument("LeastSquaresSolver: option 'algorithm' = " + SolverOptions::ToString(value) +
                                    " is not valid; use 'levenberg_marquardt' or 'gauss_newton'.");
      }
      s.gauss_newton = *text == "gauss_newton";
    } else if (name == "max_iterations") {
      s.max_iterations = AtLeastOne(name, Integer(name, value));
    } else if (name == "max_outer_iterations") {
      s.max_outer_iterations = AtLeastOne(name, Integer(name, value));
    } else if (name == "gradient_tolerance") {
      s.gradient_tolerance = NonNegative(name, Number(name, value), false);
    } else if (name == "step_tolerance") {
      s.step_tolerance = NonNegative(name, Number(name, value), false);
    } else if (name == "function_tolerance") {
      s.function_tolerance = NonNegative(name, Number(name, value), false);
    } else if (name == "initial_damping") {
      s.initial_damping = NonNegative(name, Number(name, value), true);
    } else if (name == "constraint_tol") {
      s.constraint_tol = NonNegative(name, Number(name, value), false);
    } else {
      const std::vector<std::string> closest = ClosestNames(name, kNames, 1);
      throw std::invalid_argument("LeastSquaresSolver: unknown option '" + name + "'" +
                                  (closest.empty() ? "" : " (did you mean '" + closest[0] + "'?)") +
                                  "; valid options are " + QuotedList(kNames) + ".");
    }
  }
  return s;
}

// The stacked system: residual rows of the program followed by sqrt(rho) * (A x - b + lambda / rho) rows for the
// linear equalities, with J'J's lower triangle (plus the full diagonal) in a fixed CHOLMOD-ready pattern.
class NormalEquations {
 public:
  explicit NormalEquations(ProgramAssembly* assembly) : assembly_(assembly), n_(assembly->num_vars()) {
    m_residuals_ = assembly->num_residuals();
    m_equalities_ = assembly->num_constraints();
    rows_ = assembly->residual_jacobian_rows();
    cols_ = assembly->residual_jacobian_cols();
    residual_nonzeros_ = static_cast<int>(rows_.size());
    for (int k = 0; k < assembly->jacobian_nonzeros(); ++k) {
      rows_.push_back(m_residuals_ + assembly->jacobian_rows()[static_cast<std::size_t>(k)]);
      cols_.push_back(assembly->jacobian_cols()[static_cast<std::size_t>(k)]);
    }
    const int m = m_residuals_ + m_equalities_;
    values_.resize(static_cast<Eigen::Index>(rows_.size()));
    r_.resize(m);
    g_.resize(m_equalities_);
    b_ = assembly->constraint_lower_bounds();
    lambda_ = Eigen::VectorXd::Zero(m_equalities_);

    // Group Jacobian entries by row; each pair of entries in a row contributes to one entry of J'J.
    std::vector<std::vector<int>> by_row(static_cast<std::size_t>(m));
    for (std::size_t k = 0; k < rows_.size(); ++k) {
      by_row[static_cast<std::size_t>(rows_[k])].push_back(static_cast<int>(k));
    }
    std::vector<Eigen::Triplet<double>> triplets;
    for (int i = 0; i < n_; ++i) triplets.emplace_back(i, i, 0.0);
    for (const auto& entries : by_row) {
      for (int a : entries) {
        for (int b : entries) {
          if (cols_[static_cast<std::size_t>(a)] >= cols_[static_cast<std::size_t>(b)]) {
            triplets.emplace_back(cols_[static_cast<std::size_t>(a)], cols_[static_cast<std::size_t>(b)], 0.0);
          }
        }
      }
    }
    H_.resize(n_, n_);
    H_.setFromTriplets(triplets.begin(), triplets.end());
    H_.makeCompressed();
    auto index_of = [&](int row, int col) {
      const int* begin = H_.innerIndexPtr() + H_.outerIndexPtr()[col];
      const int* end = H_.innerIndexPtr() + H_.outerIndexPtr()[col + 1];
      return static_cast<int>(std::lower_bound(begin, end, row) - H_.innerIndexPtr());
    };
    for (const auto& entries : by_row) {
      for (int a : entries) {
        for (int b : entries) {
          const int ca = cols_[static_cast<std::size_t>(a)], cb = cols_[static_cast<std::size_t>(b)];
          if (ca >= cb) products_.push_back({a, b, index_of(ca, cb)});
        }
      }
    }
    for (int i = 0; i < n_; ++i) diagonal_.push_back(index_of(i, i));
    gradient_.resize(n_);
    hessian_diagonal_.resize(n_);
    damped_ = H_;
    jacobian_step_.resize(m);
  }

  int num_equalities() const { return m_equalities_; }
  Eigen::VectorXd& lambda() { return lambda_; }
  double rho() const { return rho_; }
  void set_rho(double rho) { rho_ = rho; }
  const Eigen::VectorXd& gradient() const { return gradient_; }
  const Eigen::VectorXd& hessian_diagonal() const { return hessian_diagonal_; }

  // Objective 1/2 ||r||^2 of the stacked system at x (no derivatives).
  double Value(const double* x) {
    assembly_->EvalResiduals(x, r_.data());
    AppendEqualityRows(x, false);
    return 0.5 * r_.squaredNorm();
  }

  // Objective, gradient J'r and J'J at x.
  double Linearise(const double* x) {
    assembly_->EvalResidualsAndJacobian(x, r_.data(), values_.data());
    AppendEqualityRows(x, true);
    gradient_.setZero();
    for (std::size_t k = 0; k < rows_.size(); ++k) {
      gradient_[cols_[k]] += values_[static_cast<Eigen::Index>(k)] * r_[rows_[k]];
    }
    double* h = H_.valuePtr();
    std::fill(h, h + H_.nonZeros(), 0.0);
    for (const Product& p : products_) h[p.index] += values_[p.a] * values_[p.b];
    for (int i = 0; i < n_; ++i) hessian_diagonal_[i] = h[diagonal_[static_cast<std::size_t>(i)]];
    return 0.5 * r_.squaredNorm();
  }

  // Factorises J'J + damping * diag(scale) restricted to the free variables (rows and columns of variables held
  // at a bound become identity rows, keeping the pattern CHOLMOD analysed); returns false if CHOLMOD finds the
  // matrix not positive definite.
  bool Factorise(double damping, const Eigen::VectorXd& scale, const std::vector<char>& held) {
    std::copy(H_.valuePtr(), H_.valuePtr() + H_.nonZeros(), damped_.valuePtr());
    for (int i = 0; i < n_; ++i) damped_.valuePtr()[diagonal_[static_cast<std::size_t>(i)]] += damping * scale[i];
    for (int col = 0; col < n_; ++col) {
      for (int k = damped_.outerIndexPtr()[col]; k < damped_.outerIndexPtr()[col + 1]; ++k) {
        const int row = damped_.innerIndexPtr()[k];
        if (held[static_cast<std::size_t>(row)] || held[static_cast<std::size_t>(col)]) {
          damped_.valuePtr()[k] = row == col ? 1.0 : 0.0;
        }
      }
    }
    if (!analysed_) {
      cholmod_.analyzePattern(damped_);
      analysed_ = true;
    }
    cholmod_.factorize(damped_);
    return cholmod_.info() == Eigen::Success;
  }

  // Solves the factorised system for -gradient over the free variables (held variables do not move).
  void Step(const std::vector<char>& held, Eigen::VectorXd* step) {
    rhs_ = -gradient_;
    for (int i = 0; i < n_; ++i) {
      if (held[static_cast<std::size_t>(i)]) rhs_[i] = 0.0;
    }
    *step = cholmod_.solve(rhs_);
  }

  // ||J s||^2 for the predicted decrease of a step s.
  double JacobianStepSquaredNorm(const Eigen::VectorXd& s) {
    jacobian_step_.setZero();
    for (std::size_t k = 0; k < rows_.size(); ++k) {
      jacobian_step_[rows_[k]] += values_[static_cast<Eigen::Index>(k)] * s[cols_[k]];
    }
    return jacobian_step_.squaredNorm();
  }

  // Largest |A x - b| over the equality rows.
  double EqualityViolation(const double* x) {
    if (m_equalities_ == 0) return 0.0;
    assembly_->EvalConstraints(x, g_.data());
    return (g_ - b_).cwiseAbs().maxCoeff();
  }

  // The method-of-multipliers update lambda += rho (A x - b), with g_ from EqualityViolation.
  void UpdateMultipliers() { lambda_ += rho_ * (g_ - b_); }

 private:
  struct Product {
    int a, b, index;
  };

  void AppendEqualityRows(const double* x, bool with_jacobian) {
    if (m_equalities_ == 0) return;
    const double scale = std::sqrt(rho_);
    if (with_jacobian) {
      assembly_->EvalConstraintsAndJacobian(x, g_.data(), values_.data() + residual_nonzeros_);
      values_.tail(values_.size() - residual_nonzeros_) *= scale;
    } else {
      assembly_->EvalConstraints(x, g_.data());
    }
    r_.tail(m_equalities_) = scale * (g_ - b_ + lambda_ / rho_);
  }

  ProgramAssembly* assembly_;
  int n_;
  int m_residuals_{0};
  int m_equalities_{0};
  int residual_nonzeros_{0};
  std::vector<int> rows_, cols_;
  Eigen::VectorXd values_, r_, g_, b_, lambda_, gradient_, hessian_diagonal_, jacobian_step_, rhs_;
  double rho_{10.0};
  Eigen::SparseMatrix<double> H_, damped_;
  std::vector<Product> products_;
  std::vector<int> diagonal_;
  Eigen::CholmodDecomposition<Eigen::SparseMatrix<double>, Eigen::Lower> cholmod_;
  bool analysed_{false};
};

enum class InnerStatus { kConverged, kIterationLimit, kNumericalFailure };

// One Levenberg–Marquardt (or Gauss–Newton) run on the stacked system from x, projecting onto [lower, upper].
InnerStatus Minimise(NormalEquations* ne, const Settings& s, const Eigen::VectorXd& lower,
                     const Eigen::VectorXd& upper, Eigen::VectorXd* x, int* iterations) {
  const int n = static_cast<int>(x->size());
  double cost = ne->Linearise(x->data());
  if (!std::isfinite(cost)) return InnerStatus::kNumericalFailure;
  double damping = s.gauss_newton ? 0.0 : s.initial_damping * std::max(1.0, ne->hessian_diagonal().maxCoeff());
  double growth = 2.0;
  Eigen::VectorXd step(n), candidate(n), scale(n), taken(n);
  std::vector<char> held(static_cast<std::size_t>(n), 0);
  for (int iteration = 0; iteration < s.max_iterations; ++iteration) {
    ++*iterations;
    // Projected gradient: zero where a bound is active and the gradient pushes outwards. Such variables are held
    // at their bound for this step, so the step of the others accounts for their coupling correctly.
    double projected_gradient = 0.0;
    for (int i = 0; i < n; ++i) {
      const double moved = std::clamp((*x)[i] - ne->gradient()[i], lower[i], upper[i]);
      projected_gradient = std::max(projected_gradient, std::abs((*x)[i] - moved));
      held[static_cast<std::size_t>(i)] = ((*x)[i] <= lower[i] && ne->gradient()[i] > 0.0) ||
                                          ((*x)[i] >= upper[i] && ne->gradient()[i] < 0.0);
    }
    if (projected_gradient <= s.gradient_tolerance) return InnerStatus::kConverged;
    // Marquardt scaling, floored so a column with no data cannot make the system singular.
    const double floor = 1e-12 * std::max(1.0, ne->hessian_diagonal().maxCoeff());
    for (int i = 0; i < n; ++i) scale[i] = std::max(ne->hessian_diagonal()[i], floor);
    if (!ne->Factorise(s.gauss_newton ? floor : damping, scale, held)) {
      if (s.gauss_newton) return InnerStatus::kNumericalFailure;
      damping *= growth;
      growth *= 2.0;
      if (damping > 1e32) return InnerStatus::kNumericalFailure;
      continue;
    }
    ne->Step(held, &step);
    double alpha = 1.0;
    for (int attempt = 0; attempt < (s.gauss_newton ? 40 : 1); ++attempt, alpha *= 0.5) {
      for (int i = 0; i < n; ++i) candidate[i] = std::clamp((*x)[i] + alpha * step[i], lower[i], upper[i]);
      taken = candidate - *x;
      if (taken.norm() <= s.step_tolerance * (x->norm() + s.step_tolerance)) return InnerStatus::kConverged;
      const double predicted = -ne->gradient().dot(taken) - 0.5 * ne->JacobianStepSquaredNorm(taken);
      const double new_cost = ne->Value(candidate.data());
      const double ratio = predicted > 0.0 ? (cost - new_cost) / predicted : -1.0;
      if (std::isfinite(new_cost) && new_cost < cost && ratio > (s.gauss_newton ? 1e-4 : 0.0)) {
        const double decrease = cost - new_cost;
        *x = candidate;
        cost = ne->Linearise(x->data());
        if (!s.gauss_newton) {
          damping *= std::max(1.0 / 3.0, 1.0 - std::pow(2.0 * ratio - 1.0, 3));
          growth = 2.0;
        }
        if (decrease <= s.function_tolerance * cost) return InnerStatus::kConverged;
        break;
      }
      if (!s.gauss_newton) {
        damping *= growth;
        growth *= 2.0;
        if (damping > 1e32) return InnerStatus::kNumericalFailure;
      } else if (attempt == 39) {
        return InnerStatus::kNumericalFailure;
      }
    }
  }
  return InnerStatus::kIterationLimit;
}

}  // namespace

LeastSquaresSolver::LeastSquaresSolver() : Solver("least_squares", "least_squares") {}

std::string LeastSquaresSolver::DoCheckSupport(const MathematicalProgram& prog) const {
  if (!prog.costs().empty()) {
    return "LeastSquaresSolver: the cost '" + prog.costs().front().ToString() +
           "' is not a least-squares cost; add it as a residual with AddLeastSquaresCost, or use 'ipopt' or "
           "'nlopt:SLSQP' for general costs.";
  }
  if (prog.least_squares_costs().empty()) {
    return "LeastSquaresSolver: the program has no least-squares costs; add residuals with AddLeastSquaresCost.";
  }
  for (const auto& binding : prog.constraints()) {
    if (dynamic_cast<const LinearEqualityConstraint*>(binding.evaluator().get()) == nullptr) {
      return "LeastSquaresSolver: the constraint '" + binding.ToString() +
             "' is not a linear equality; the least-squares solver supports bounding boxes and "
             "LinearEqualityConstraints only, so use 'ipopt' for this program.";
    }
  }
  return "";
}

SolverResult LeastSquaresSolver::DoSolve(const MathematicalProgram& prog, const Eigen::VectorXd& initial_guess,
                                         const SolverOptions::OptionMap& options) const {
  const Settings settings = ParseOptions(options);
  ProgramAssembly assembly(prog);
  NormalEquations ne(&assembly);
  const Eigen::VectorXd& lower = assembly.variable_lower_bounds();
  const Eigen::VectorXd& upper = assembly.variable_upper_bounds();
  Eigen::VectorXd x = initial_guess.cwiseMax(lower).cwiseMin(upper);

  SolverResult result;
  result.iterations = 0;
  InnerStatus inner = InnerStatus::kConverged;
  double violation = 0.0;
  int outer = 0;
  for (; outer < settings.max_outer_iterations; ++outer) {
    inner = Minimise(&ne, settings, lower, upper, &x, &result.iterations);
    if (inner != InnerStatus::kConverged || ne.num_equalities() == 0) break;
    const double previous = violation;
    violation = ne.EqualityViolation(x.data());
    if (violation <= settings.constraint_tol) break;
    ne.UpdateMultipliers();
    // Raise the penalty when the multipliers alone do not shrink the violation fast enough.
    if (outer > 0 && violation > 0.25 * previous) ne.set_rho(ne.rho() * 10.0);
  }
  violation = ne.EqualityViolation(x.data());

  result.x = x;
  result.objective = assembly.EvalCost(x.data());
  result.constraint_violation = assembly.ConstraintViolation(x.data());
  if (ne.num_equalities() > 0) result.constraint_duals = ne.lambda();
  switch (inner) {
    case InnerStatus::kConverged:
      result.status = violation <= settings.constraint_tol ? SolutionStatus::kSolved : SolutionStatus::kInfeasible;
      result.message = violation <= settings.constraint_tol
                           ? "converged"
                           : "converged, but the linear equalities are violated by " + std::to_string(violation) +
                                 " after " + std::to_string(outer) + " multiplier updates";
      break;
    case InnerStatus::kIterationLimit:
      result.status = SolutionStatus::kIterationLimit;
      result.message = "reached max_iterations = " + std::to_string(settings.max_iterations);
      break;
    case InnerStatus::kNumericalFailure:
      result.status = SolutionStatus::kNumericalFailure;
      result.message = "the damped normal equations could not be factorised or the residuals are not finite";
      break;
  }
  return result;
}

}  // namespace cairn::optimization
