#include "cairn/optimization/program_assembly.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>
#include <sstream>

#include "cairn/common/cairn_assert.h"

namespace cairn::optimization {

ProgramAssembly::ProgramAssembly(const MathematicalProgram& prog, LeastSquaresHessian least_squares_hessian)
    : prog_(&prog),
      least_squares_hessian_(least_squares_hessian),
      num_vars_(prog.num_vars()),
      x_lower_(prog.variable_lower_bounds()),
      x_upper_(prog.variable_upper_bounds()) {
  int x_size = 0, y_size = 0, jac_size = 0, hess_size = 0;
  has_hessian_ = true;
  // Reserve everything up front: tiny programs are solved hundreds of thousands of times, and reallocation
  // would dominate their set-up.
  std::size_t total_vars = 0, total_jacobian = 0, total_residual_jacobian = 0;
  for (const auto& b : prog.costs()) total_vars += b.variables().indices().size();
  for (const auto& b : prog.least_squares_costs()) {
    total_vars += b.variables().indices().size();
    total_residual_jacobian += b.evaluator()->jacobian_pattern().size();
  }
  for (const auto& b : prog.constraints()) {
    total_vars += b.variables().indices().size();
    total_jacobian += b.evaluator()->jacobian_pattern().size();
  }
  var_indices_.reserve(total_vars);
  jacobian_rows_.reserve(total_jacobian);
  jacobian_cols_.reserve(total_jacobian);
  residual_rows_.reserve(total_residual_jacobian);
  residual_cols_.reserve(total_residual_jacobian);
  cost_terms_.reserve(prog.costs().size());
  least_squares_terms_.reserve(prog.least_squares_costs().size());
  constraint_terms_.reserve(prog.constraints().size());
  auto make_term = [&](const auto& binding, bool is_constraint, bool is_least_squares = false) {
    Term term;
    term.evaluator = binding.evaluator().get();
    term.var_offset = static_cast<int>(var_indices_.size());
    term.num_inputs = binding.variables().size();
    var_indices_.insert(var_indices_.end(), binding.variables().indices().begin(),
                        binding.variables().indices().end());
    term.x_offset = x_size;
    x_size += term.num_inputs;
    if (is_constraint) {
      term.row_offset = num_rows_;
      num_rows_ += term.evaluator->num_outputs();
      term.jac_offset = static_cast<int>(jacobian_rows_.size());
      for (const SparsityEntry& e : term.evaluator->jacobian_pattern()) {
        jacobian_rows_.push_back(term.row_offset + e.row);
        jacobian_cols_.push_back(binding.variables().indices()[static_cast<std::size_t>(e.col)]);
      }
    } else {
      term.y_offset = y_size;
      y_size += term.evaluator->num_outputs();
      term.jac_offset = jac_size;
      jac_size += term.evaluator->jacobian_nonzeros();
    }
    term.hess_offset = hess_size;
    const bool gauss_newton = is_least_squares && least_squares_hessian == LeastSquaresHessian::kGaussNewton;
    if (term.evaluator->has_hessian() && !gauss_newton) {
      term.hess_pattern = term.evaluator->hessian_pattern();
      hess_size += static_cast<int>(term.hess_pattern.size());
    }
    return term;
  };
  for (const auto& cost : prog.costs()) {
    cost_terms_.push_back(make_term(cost, false));
    has_hessian_ = has_hessian_ && cost.evaluator()->has_hessian();
  }
  for (const auto& cost : prog.least_squares_costs()) {
    least_squares_terms_.push_back(make_term(cost, false, true));
    Term& term = least_squares_terms_.back();
    term.row_offset = num_residuals_;
    num_residuals_ += term.evaluator->num_outputs();
    term.residual_jac_offset = static_cast<int>(residual_rows_.size());
    for (const SparsityEntry& e : term.evaluator->jacobian_pattern()) {
      residual_rows_.push_back(term.row_offset + e.row);
      residual_cols_.push_back(cost.variables().indices()[static_cast<std::size_t>(e.col)]);
    }
    if (!term.evaluator->has_hessian() && least_squares_hessian_ == LeastSquaresHessian::kExact) {
      has_hessian_ = false;
    } else {
      // Hessian of 1/2 ||r||^2 = J'J + sum_k r_k Hessian(r_k): the local pattern is the union of the J'J pairs
      // (entries of one Jacobian row) and the residual's declared Hessian pattern.
      hess_size -= static_cast<int>(term.hess_pattern.size());
      const std::vector<SparsityEntry>& jac = term.evaluator->jacobian_pattern();
      std::vector<std::pair<int, int>> local;  // (row, col), row >= col
      std::vector<std::array<int, 3>> pairs;   // (entry a, entry b, position in `local` filled below)
      // Entries grouped by row, so the pairs cost sum over rows of nnz(row)^2, not nnz^2.
      std::vector<int> by_row(jac.size());
      std::iota(by_row.begin(), by_row.end(), 0);
      std::stable_sort(by_row.begin(), by_row.end(), [&](int a, int b) { return jac[a].row < jac[b].row; });
      for (std::size_t begin = 0; begin < by_row.size();) {
        std::size_t end = begin;
        while (end < by_row.size() && jac[by_row[end]].row == jac[by_row[begin]].row) ++end;
        for (std::size_t i = begin; i < end; ++i) {
          for (std::size_t j = begin; j <= i; ++j) {
            const SparsityEntry& a = jac[by_row[i]];
            const SparsityEntry& b = jac[by_row[j]];
            local.emplace_back(std::max(a.col, b.col), std::min(a.col, b.col));
            pairs.push_back({by_row[i], by_row[j], 0});
          }
        }
        begin = end;
      }
      for (const SparsityEntry& e : term.hess_pattern) local.emplace_back(e.row, e.col);
      std::vector<std::pair<int, int>> unique_local = local;
      std::sort(unique_local.begin(), unique_local.end());
      unique_local.erase(std::unique(unique_local.begin(), unique_local.end()), unique_local.end());
      auto position = [&](const std::pair<int, int>& e) {
        return static_cast<int>(std::lower_bound(unique_local.begin(), unique_local.end(), e) -
                                unique_local.begin());
      };
      term.ls_pair_offset = static_cast<int>(ls_pairs_.size());
      for (std::size_t k = 0; k < pairs.size(); ++k) {
        ls_pairs_.push_back({pairs[k][0], pairs[k][1], position(local[k])});
      }
      term.ls_pair_count = static_cast<int>(pairs.size());
      term.residual_hess_offset = static_cast<int>(ls_residual_hess_map_.size());
      for (std::size_t k = pairs.size(); k < local.size(); ++k) ls_residual_hess_map_.push_back(position(local[k]));
      term.hess_pattern.clear();
      for (const auto& e : unique_local) term.hess_pattern.push_back({e.first, e.second});
      term.hess_offset = hess_size;
      hess_size += static_cast<int>(term.hess_pattern.size());
    }
  }
  for (const auto& constraint : prog.constraints()) {
    constraint_terms_.push_back(make_term(constraint, true));
    has_hessian_ = has_hessian_ && constraint.evaluator()->has_hessian();
  }
  x_local_.resize(x_size);
  y_local_.resize(y_size);
  jac_local_.resize(jac_size);
  g_scratch_.resize(num_rows_);
  g_lower_.resize(num_rows_);
  g_upper_.resize(num_rows_);
  for (std::size_t i = 0; i < constraint_terms_.size(); ++i) {
    const Constraint& c = *prog.constraints()[i].evaluator();
    g_lower_.segment(constraint_terms_[i].row_offset, c.num_outputs()) = c.lower_bound();
    g_upper_.segment(constraint_terms_[i].row_offset, c.num_outputs()) = c.upper_bound();
  }

  if (has_hessian_) {
    // Map every term's local lower-triangle entries to unique global (row >= col) entries, sorted column-major.
    std::vector<std::int64_t> keys;
    keys.reserve(static_cast<std::size_t>(hess_size));
    auto collect = [&](const std::vector<Term>& terms) {
      for (const Term& term : terms) {
        for (const SparsityEntry& e : term.hess_pattern) {
          int r = var_indices_[static_cast<std::size_t>(term.var_offset + e.row)];
          int c = var_indices_[static_cast<std::size_t>(term.var_offset + e.col)];
          if (r < c) std::swap(r, c);
          keys.push_back(static_cast<std::int64_t>(c) * num_vars_ + r);
        }
      }
    };
    collect(cost_terms_);
    collect(least_squares_terms_);
    collect(constraint_terms_);
    std::vector<std::int64_t> unique_keys = keys;
    std::sort(unique_keys.begin(), unique_keys.end());
    unique_keys.erase(std::unique(unique_keys.begin(), unique_keys.end()), unique_keys.end());
    hess_map_.resize(keys.size());
    for (std::size_t k = 0; k < keys.size(); ++k) {
      hess_map_[k] = static_cast<int>(std::lower_bound(unique_keys.begin(), unique_keys.end(), keys[k]) -
                                      unique_keys.begin());
    }
    for (const std::int64_t key : unique_keys) {
      hessian_cols_.push_back(static_cast<int>(key / num_vars_));
      hessian_rows_.push_back(static_cast<int>(key % num_vars_));
    }
    hess_local_.resize(hess_size);
    residual_hess_local_.resize(static_cast<Eigen::Index>(ls_residual_hess_map_.size()));
  }
}

void ProgramAssembly::Gather(const Term& term, const double* x) {
  const int* indices = var_indices_.data() + term.var_offset;
  double* local = x_local_.data() + term.x_offset;
  for (int i = 0; i < term.num_inputs; ++i) local[i] = x[indices[i]];
}

double ProgramAssembly::EvalCost(const double* x) {
  double total = 0.0;
  for (const Term& term : cost_terms_) {
    Gather(term, x);
    auto y = y_local_.segment(term.y_offset, 1);
    term.evaluator->DoEval(x_local_.segment(term.x_offset, term.num_inputs), y);
    total += y[0];
  }
  for (const Term& term : least_squares_terms_) {
    Gather(term, x);
    auto r = y_local_.segment(term.y_offset, term.evaluator->num_outputs());
    term.evaluator->DoEval(x_local_.segment(term.x_offset, term.num_inputs), r);
    total += 0.5 * r.squaredNorm();
  }
  return total;
}

double ProgramAssembly::EvalCostAndGradient(const double* x, double* gradient) {
  std::fill(gradient, gradient + num_vars_, 0.0);
  double total = 0.0;
  for (const Term& term : cost_terms_) {
    Gather(term, x);
    auto y = y_local_.segment(term.y_offset, 1);
    auto jac = jac_local_.segment(term.jac_offset, term.evaluator->jacobian_nonzeros());
    term.evaluator->DoEvalWithJacobian(x_local_.segment(term.x_offset, term.num_inputs), y, jac);
    total += y[0];
    const int* indices = var_indices_.data() + term.var_offset;
    const std::vector<SparsityEntry>& pattern = term.evaluator->jacobian_pattern();
    for (std::size_t k = 0; k < pattern.size(); ++k) {
      gradient[indices[pattern[k].col]] += jac[static_cast<Eigen::Index>(k)];
    }
  }
  for (const Term& term : least_squares_terms_) {
    Gather(term, x);
    auto r = y_local_.segment(term.y_offset, term.evaluator->num_outputs());
    auto jac = jac_local_.segment(term.jac_offset, term.evaluator->jacobian_nonzeros());
    term.evaluator->DoEvalWithJacobian(x_local_.segment(term.x_offset, term.num_inputs), r, jac);
    total += 0.5 * r.squaredNorm();
    const int* indices = var_indices_.data() + term.var_offset;
    const std::vector<SparsityEntry>& pattern = term.evaluator->jacobian_pattern();
    for (std::size_t k = 0; k < pattern.size(); ++k) {
      gradient[indices[pattern[k].col]] += jac[static_cast<Eigen::Index>(k)] * r[pattern[k].row];
    }
  }
  return total;
}

void ProgramAssembly::EvalResiduals(const double* x, double* r) {
  for (const Term& term : least_squares_terms_) {
    Gather(term, x);
    Eigen::Map<Eigen::VectorXd> y(r + term.row_offset, term.evaluator->num_outputs());
    term.evaluator->DoEval(x_local_.segment(term.x_offset, term.num_inputs), y);
  }
}

void ProgramAssembly::EvalResidualsAndJacobian(const double* x, double* r, double* jacobian_values) {
  for (const Term& term : least_squares_terms_) {
    Gather(term, x);
    Eigen::Map<Eigen::VectorXd> y(r + term.row_offset, term.evaluator->num_outputs());
    Eigen::Map<Eigen::VectorXd> jac(jacobian_values + term.residual_jac_offset, term.evaluator->jacobian_nonzeros());
    term.evaluator->DoEvalWithJacobian(x_local_.segment(term.x_offset, term.num_inputs), y, jac);
  }
}

void ProgramAssembly::EvalConstraints(const double* x, double* g) {
  for (const Term& term : constraint_terms_) {
    Gather(term, x);
    Eigen::Map<Eigen::VectorXd> y(g + term.row_offset, term.evaluator->num_outputs());
    term.evaluator->DoEval(x_local_.segment(term.x_offset, term.num_inputs), y);
  }
}

void ProgramAssembly::EvalConstraintsAndJacobian(const double* x, double* g, double* jacobian_values) {
  double* values = g != nullptr ? g : g_scratch_.data();
  for (const Term& term : constraint_terms_) {
    Gather(term, x);
    Eigen::Map<Eigen::VectorXd> y(values + term.row_offset, term.evaluator->num_outputs());
    Eigen::Map<Eigen::VectorXd> jac(jacobian_values + term.jac_offset, term.evaluator->jacobian_nonzeros());
    term.evaluator->DoEvalWithJacobian(x_local_.segment(term.x_offset, term.num_inputs), y, jac);
  }
}

void ProgramAssembly::EvalLagrangianHessian(const double* x, double objective_factor, const double* lambda,
                                            double* values) {
  CAIRN_CHECK(has_hessian_);
  std::fill(values, values + hessian_rows_.size(), 0.0);
  auto accumulate = [&](const Term& term, const double* weights) {
    const int count = static_cast<int>(term.hess_pattern.size());
    if (count == 0) return;
    Gather(term, x);
    auto local = hess_local_.segment(term.hess_offset, count);
    term.evaluator->DoEvalHessian(x_local_.segment(term.x_offset, term.num_inputs),
                                Eigen::Map<const Eigen::VectorXd>(weights, term.evaluator->num_outputs()), local);
    for (int k = 0; k < count; ++k) values[hess_map_[static_cast<std::size_t>(term.hess_offset + k)]] += local[k];
  };
  for (const Term& term : cost_terms_) accumulate(term, &objective_factor);
  for (const Term& term : least_squares_terms_) {
    const int count = static_cast<int>(term.hess_pattern.size());
    Gather(term, x);
    const auto x_local = x_local_.segment(term.x_offset, term.num_inputs);
    auto r = y_local_.segment(term.y_offset, term.evaluator->num_outputs());
    auto jac = jac_local_.segment(term.jac_offset, term.evaluator->jacobian_nonzeros());
    term.evaluator->DoEvalWithJacobian(x_local, r, jac);
    auto local = hess_local_.segment(term.hess_offset, count);
    local.setZero();
    for (int k = 0; k < term.ls_pair_count; ++k) {
      const LeastSquaresPair& p = ls_pairs_[static_cast<std::size_t>(term.ls_pair_offset + k)];
      local[p.local] += jac[p.a] * jac[p.b];
    }
    const int residual_count = least_squares_hessian_ == LeastSquaresHessian::kGaussNewton || !term.evaluator->has_hessian()
                                   ? 0
                                   : static_cast<int>(term.evaluator->hessian_pattern().size());
    if (residual_count > 0) {
      auto residual_hessian = residual_hess_local_.segment(term.residual_hess_offset, residual_count);
      term.evaluator->DoEvalHessian(x_local, r, residual_hessian);
      for (int k = 0; k < residual_count; ++k) {
        local[ls_residual_hess_map_[static_cast<std::size_t>(term.residual_hess_offset + k)]] += residual_hessian[k];
      }
    }
    for (int k = 0; k < count; ++k) {
      values[hess_map_[static_cast<std::size_t>(term.hess_offset + k)]] += objective_factor * local[k];
    }
  }
  for (const Term& term : constraint_terms_) accumulate(term, lambda + term.row_offset);
}

double ProgramAssembly::ConstraintViolation(const double* x) {
  double violation = 0.0;
  for (int i = 0; i < num_vars_; ++i) {
    violation = std::max({violation, x_lower_[i] - x[i], x[i] - x_upper_[i]});
  }
  EvalConstraints(x, g_scratch_.data());
  for (int i = 0; i < num_rows_; ++i) {
    violation = std::max({violation, g_lower_[i] - g_scratch_[i], g_scratch_[i] - g_upper_[i]});
  }
  if (std::isnan(violation)) return std::numeric_limits<double>::infinity();
  return violation;
}

std::string ProgramAssembly::DescribeWorstViolation(const double* x) {
  double worst = 0.0;
  std::ostringstream out;
  for (int i = 0; i < num_vars_; ++i) {
    const double v = std::max(x_lower_[i] - x[i], x[i] - x_upper_[i]);
    if (v > worst) {
      worst = v;
      out.str("");
      out << "variable '" << prog_->VariableName(i) << "' = " << x[i] << " outside its bounds [" << x_lower_[i]
          << ", " << x_upper_[i] << "]";
    }
  }
  EvalConstraints(x, g_scratch_.data());
  for (std::size_t t = 0; t < constraint_terms_.size(); ++t) {
    const Term& term = constraint_terms_[t];
    for (int r = 0; r < term.evaluator->num_outputs(); ++r) {
      const int row = term.row_offset + r;
      const double v = std::max(g_lower_[row] - g_scratch_[row], g_scratch_[row] - g_upper_[row]);
      if (v > worst) {
        worst = v;
        out.str("");
        out << "constraint '" << prog_->constraints()[t].ToString() << "' row " << r << " (value " << g_scratch_[row]
            << ", bounds [" << g_lower_[row] << ", " << g_upper_[row] << "])";
      }
    }
  }
  return worst > 0.0 ? out.str() : std::string();
}

}  // namespace cairn::optimization
