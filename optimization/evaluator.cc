#include "cairn/common/number_text.h"
#include "cairn/optimization/evaluator.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <numeric>
#include <stdexcept>

#include "cairn/common/cairn_assert.h"

namespace cairn::optimization {

const char* to_string(DerivativeSource source) {
  switch (source) {
    case DerivativeSource::kAnalytic:
      return "analytic";
    case DerivativeSource::kAutoDiff:
      return "autodiff";
    case DerivativeSource::kFiniteDifference:
      return "finite differences";
  }
  return "unknown";
}

namespace {

void ValidatePattern(const std::string& evaluator, const char* what, const std::vector<SparsityEntry>& pattern,
                     int rows, int cols, bool lower_triangle) {
  std::vector<std::pair<int, int>> sorted;
  sorted.reserve(pattern.size());
  for (const SparsityEntry& e : pattern) {
    if (e.row < 0 || e.row >= rows || e.col < 0 || e.col >= cols) {
      throw std::invalid_argument("Evaluator '" + evaluator + "': " + what + " entry (" + cairn::FormatShort(e.row) +
                                  ", " + cairn::FormatShort(e.col) + ") is outside the " + cairn::FormatShort(rows) +
                                  " x " + cairn::FormatShort(cols) + " matrix; declare entries with 0 <= row < " +
                                  cairn::FormatShort(rows) + " and 0 <= col < " + cairn::FormatShort(cols) + ".");
    }
    if (lower_triangle && e.row < e.col) {
      throw std::invalid_argument("Evaluator '" + evaluator + "': " + what + " entry (" + cairn::FormatShort(e.row) +
                                  ", " + cairn::FormatShort(e.col) +
                                  ") is above the diagonal; declare the lower triangle only (row >= col).");
    }
    sorted.emplace_back(e.row, e.col);
  }
  std::sort(sorted.begin(), sorted.end());
  const auto dup = std::adjacent_find(sorted.begin(), sorted.end());
  if (dup != sorted.end()) {
    throw std::invalid_argument("Evaluator '" + evaluator + "': " + what + " entry (" + cairn::FormatShort(dup->first) +
                                ", " + cairn::FormatShort(dup->second) + ") is declared twice; list each entry once.");
  }
}

struct FiniteDifferenceScratch {
  Eigen::VectorXd x;
  Eigen::VectorXd y_plus;
  Eigen::VectorXd y_minus;
};

// Per-thread scratch, one level per nested finite-difference evaluation (a value function may itself evaluate
// another finite-difference evaluator), so steady-state calls do not allocate and nesting cannot clobber.
class ScratchLevel {
 public:
  ScratchLevel() {
    if (pool().size() <= depth()) pool().push_back(std::make_unique<FiniteDifferenceScratch>());
    scratch_ = pool()[depth()].get();
    ++depth();
  }
  ~ScratchLevel() { --depth(); }
  ScratchLevel(const ScratchLevel&) = delete;
  ScratchLevel& operator=(const ScratchLevel&) = delete;
  FiniteDifferenceScratch& scratch() { return *scratch_; }

 private:
  static std::vector<std::unique_ptr<FiniteDifferenceScratch>>& pool() {
    thread_local std::vector<std::unique_ptr<FiniteDifferenceScratch>> levels;
    return levels;
  }
  static std::size_t& depth() {
    thread_local std::size_t level = 0;
    return level;
  }
  FiniteDifferenceScratch* scratch_;
};

}  // namespace

Evaluator::Evaluator(std::string name, int num_inputs, int num_outputs, std::vector<SparsityEntry> jacobian_pattern,
                     DerivativeSource jacobian_source)
    : name_(std::move(name)),
      num_inputs_(num_inputs),
      num_outputs_(num_outputs),
      jacobian_pattern_(std::move(jacobian_pattern)),
      jacobian_source_(jacobian_source) {
  if (num_inputs < 0 || num_outputs < 0) {
    throw std::invalid_argument("Evaluator '" + name_ + "': num_inputs = " + cairn::FormatShort(num_inputs) +
                                " and num_outputs = " + cairn::FormatShort(num_outputs) + " must be >= 0.");
  }
  ValidatePattern(name_, "Jacobian pattern", jacobian_pattern_, num_outputs, num_inputs, false);
  std::vector<int> order(jacobian_pattern_.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(),
                   [&](int a, int b) { return jacobian_pattern_[a].col < jacobian_pattern_[b].col; });
  column_order_ = order;
  for (std::size_t k = 0; k < order.size(); ++k) {
    const int col = jacobian_pattern_[order[k]].col;
    if (fd_columns_.empty() || fd_columns_.back() != col) {
      fd_columns_.push_back(col);
      column_starts_.push_back(static_cast<int>(k));
    }
  }
  column_starts_.push_back(static_cast<int>(order.size()));
}

Evaluator::~Evaluator() = default;

void Evaluator::DeclareHessianPattern(std::vector<SparsityEntry> hessian_pattern) {
  ValidatePattern(name_, "Hessian pattern", hessian_pattern, num_inputs_, num_inputs_, true);
  hessian_pattern_ = std::move(hessian_pattern);
  has_hessian_ = true;
}

void Evaluator::CheckInputSize(const Eigen::Ref<const Eigen::VectorXd>& x, const char* method) const {
  if (x.size() != num_inputs_) {
    throw std::invalid_argument("Evaluator '" + name_ + "'." + method + ": x has size " + cairn::FormatShort(x.size()) +
                                " but the evaluator takes " + cairn::FormatShort(num_inputs_) + " inputs.");
  }
}

void Evaluator::Eval(const Eigen::Ref<const Eigen::VectorXd>& x, Eigen::Ref<Eigen::VectorXd> y) const {
  CheckInputSize(x, "Eval");
  if (y.size() != num_outputs_) {
    throw std::invalid_argument("Evaluator '" + name_ + "'.Eval: y has size " + cairn::FormatShort(y.size()) +
                                " but the evaluator has " + cairn::FormatShort(num_outputs_) + " outputs.");
  }
  DoEval(x, y);
}

Eigen::VectorXd Evaluator::Eval(const Eigen::Ref<const Eigen::VectorXd>& x) const {
  Eigen::VectorXd y(num_outputs_);
  Eval(x, y);
  return y;
}

void Evaluator::EvalWithJacobian(const Eigen::Ref<const Eigen::VectorXd>& x, Eigen::Ref<Eigen::VectorXd> y,
                                 Eigen::Ref<Eigen::VectorXd> jacobian_values) const {
  CheckInputSize(x, "EvalWithJacobian");
  if (y.size() != num_outputs_ || jacobian_values.size() != jacobian_nonzeros()) {
    throw std::invalid_argument("Evaluator '" + name_ + "'.EvalWithJacobian: y has size " +
                                cairn::FormatShort(y.size()) + " and jacobian_values " +
                                cairn::FormatShort(jacobian_values.size()) + "; expected " +
                                cairn::FormatShort(num_outputs_) + " and " + cairn::FormatShort(jacobian_nonzeros()) +
                                " (one per pattern entry).");
  }
  DoEvalWithJacobian(x, y, jacobian_values);
}

Eigen::SparseMatrix<double> Evaluator::EvalJacobian(const Eigen::Ref<const Eigen::VectorXd>& x) const {
  Eigen::VectorXd y(num_outputs_);
  Eigen::VectorXd values(jacobian_nonzeros());
  EvalWithJacobian(x, y, values);
  std::vector<Eigen::Triplet<double>> triplets;
  triplets.reserve(jacobian_pattern_.size());
  for (std::size_t k = 0; k < jacobian_pattern_.size(); ++k) {
    triplets.emplace_back(jacobian_pattern_[k].row, jacobian_pattern_[k].col, values[static_cast<Eigen::Index>(k)]);
  }
  Eigen::SparseMatrix<double> jacobian(num_outputs_, num_inputs_);
  jacobian.setFromTriplets(triplets.begin(), triplets.end());
  return jacobian;
}

void Evaluator::EvalHessian(const Eigen::Ref<const Eigen::VectorXd>& x,
                            const Eigen::Ref<const Eigen::VectorXd>& weights,
                            Eigen::Ref<Eigen::VectorXd> hessian_values) const {
  if (!has_hessian_) {
    throw std::logic_error("Evaluator '" + name_ +
                           "' has no Hessian; check has_hessian() before calling EvalHessian.");
  }
  CheckInputSize(x, "EvalHessian");
  if (weights.size() != num_outputs_ || hessian_values.size() != static_cast<Eigen::Index>(hessian_pattern_.size())) {
    throw std::invalid_argument("Evaluator '" + name_ + "'.EvalHessian: weights has size " +
                                cairn::FormatShort(weights.size()) + " and hessian_values " +
                                cairn::FormatShort(hessian_values.size()) + "; expected " +
                                cairn::FormatShort(num_outputs_) + " and " + cairn::FormatShort(hessian_pattern_.size()) +
                                ".");
  }
  DoEvalHessian(x, weights, hessian_values);
}

std::vector<SparsityEntry> Evaluator::DensePattern(int rows, int cols) {
  std::vector<SparsityEntry> pattern;
  pattern.reserve(static_cast<std::size_t>(std::max(0, rows * cols)));
  for (int r = 0; r < rows; ++r) {
    for (int c = 0; c < cols; ++c) pattern.push_back({r, c});
  }
  return pattern;
}

void Evaluator::DoEvalWithJacobian(const Eigen::Ref<const Eigen::VectorXd>& x, Eigen::Ref<Eigen::VectorXd> y,
                                   Eigen::Ref<Eigen::VectorXd> jacobian_values) const {
  FiniteDifferenceJacobian(x, y, jacobian_values);
}

void Evaluator::DoEvalHessian(const Eigen::Ref<const Eigen::VectorXd>&, const Eigen::Ref<const Eigen::VectorXd>&,
                              Eigen::Ref<Eigen::VectorXd>) const {
  // DeclareHessianPattern promises an override; reaching this is a bug in the subclass.
  CAIRN_CHECK(!has_hessian_);
}

void Evaluator::FiniteDifferenceJacobian(const Eigen::Ref<const Eigen::VectorXd>& x, Eigen::Ref<Eigen::VectorXd> y,
                                         Eigen::Ref<Eigen::VectorXd> jacobian_values) const {
  DoEval(x, y);
  ScratchLevel level;
  FiniteDifferenceScratch& scratch = level.scratch();
  scratch.x = x;  // Resizes only when this thread sees a larger evaluator.
  if (scratch.y_plus.size() != num_outputs_) {
    scratch.y_plus.resize(num_outputs_);
    scratch.y_minus.resize(num_outputs_);
  }
  // Central differences: O(h^2) truncation error, so h ~ eps^(1/3) balances truncation and round-off.
  const double relative_step = std::cbrt(std::numeric_limits<double>::epsilon());
  for (std::size_t k = 0; k < fd_columns_.size(); ++k) {
    const int col = fd_columns_[k];
    const double xj = x[col];
    const double h = relative_step * std::max(1.0, std::abs(xj));
    scratch.x[col] = xj + h;
    DoEval(scratch.x, scratch.y_plus);
    scratch.x[col] = xj - h;
    DoEval(scratch.x, scratch.y_minus);
    scratch.x[col] = xj;
    for (int i = column_starts_[k]; i < column_starts_[k + 1]; ++i) {
      const int entry = column_order_[static_cast<std::size_t>(i)];
      const int row = jacobian_pattern_[static_cast<std::size_t>(entry)].row;
      jacobian_values[entry] = (scratch.y_plus[row] - scratch.y_minus[row]) / (2.0 * h);
    }
  }
}

}  // namespace cairn::optimization
