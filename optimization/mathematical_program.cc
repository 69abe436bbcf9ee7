#include "cairn/common/number_text.h"
#include "cairn/optimization/mathematical_program.h"

#include <algorithm>
#include <atomic>
#include <limits>
#include <stdexcept>

#include "cairn/common/text_suggestions.h"
#include "cairn/optimization/evaluator_constraint.h"

namespace cairn::optimization {

namespace {

std::int64_t NextProgramId() {
  static std::atomic<std::int64_t> next{1};
  return next++;
}

}  // namespace

MathematicalProgram::MathematicalProgram() : id_(NextProgramId()) {}

DecisionVariables MathematicalProgram::NewContinuousVariables(int n, const std::string& name) {
  if (n < 1) {
    throw std::invalid_argument("NewContinuousVariables(" + cairn::FormatShort(n) + ", '" + name +
                                "'): the number of variables must be at least 1.");
  }
  if (name.empty()) {
    throw std::invalid_argument("NewContinuousVariables(" + cairn::FormatShort(n) +
                                ", ''): give the variables a name; it appears in every message about them.");
  }
  for (const DecisionVariables& block : blocks_) {
    if (block.description() == name) {
      throw std::invalid_argument("NewContinuousVariables: a variable block named '" + name +
                                  "' already exists; choose another name so messages stay unambiguous.");
    }
  }
  const int start = num_vars();
  std::vector<int> indices(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) {
    indices[static_cast<std::size_t>(i)] = start + i;
    variable_names_.push_back(n == 1 ? name : name + "(" + cairn::FormatShort(i) + ")");
  }
  initial_guess_.conservativeResize(start + n);
  initial_guess_.tail(n).setZero();
  blocks_.push_back(DecisionVariables::FromIndices(id_, std::move(indices), name));
  return blocks_.back();
}

const std::string& MathematicalProgram::VariableName(int index) const {
  if (index < 0 || index >= num_vars()) {
    throw std::invalid_argument("VariableName(" + cairn::FormatShort(index) + "): the program has " +
                                cairn::FormatShort(num_vars()) + " variables; pass 0 <= index < " +
                                cairn::FormatShort(num_vars()) + ".");
  }
  return variable_names_[static_cast<std::size_t>(index)];
}

const DecisionVariables& MathematicalProgram::GetVariables(const std::string& name) const {
  std::vector<std::string> names;
  for (const DecisionVariables& block : blocks_) {
    if (block.description() == name) return block;
    names.push_back(block.description());
  }
  const std::vector<std::string> closest = ClosestNames(name, names);
  throw std::invalid_argument("GetVariables: no variable block named '" + name + "'" +
                              (closest.empty() ? std::string(" (the program has no variables yet)")
                                               : "; did you mean " + QuotedList(closest) + "?"));
}

void MathematicalProgram::CheckVariables(const DecisionVariables& vars, const std::string& what) const {
  if (vars.empty()) {
    throw std::invalid_argument(what + ": the variable list is empty; bind at least one variable.");
  }
  if (vars.program_id() != id_) {
    throw std::invalid_argument(what + ": the variables '" + vars.description() +
                                "' were created by a different MathematicalProgram; use variables returned by this "
                                "program's NewContinuousVariables.");
  }
  std::vector<int> sorted = vars.indices();
  std::sort(sorted.begin(), sorted.end());
  const auto dup = std::adjacent_find(sorted.begin(), sorted.end());
  if (dup != sorted.end()) {
    throw std::invalid_argument(what + ": variable '" + VariableName(*dup) + "' appears twice in '" +
                                vars.description() + "'; bind each variable once.");
  }
}

void MathematicalProgram::CheckDecisionVectorSize(const Eigen::Ref<const Eigen::VectorXd>& x,
                                                  const char* method) const {
  if (x.size() != num_vars()) {
    throw std::invalid_argument(std::string(method) + ": x has size " + cairn::FormatShort(x.size()) +
                                " but the program has " + cairn::FormatShort(num_vars()) + " variables.");
  }
}

void MathematicalProgram::SetInitialGuess(const DecisionVariables& vars,
                                          const Eigen::Ref<const Eigen::VectorXd>& values) {
  CheckVariables(vars, "SetInitialGuess");
  if (values.size() != vars.size()) {
    throw std::invalid_argument("SetInitialGuess('" + vars.description() + "'): got " +
                                cairn::FormatShort(values.size()) + " values for " + cairn::FormatShort(vars.size()) +
                                " variables; pass one value per variable.");
  }
  for (int i = 0; i < vars.size(); ++i) initial_guess_[vars.indices()[static_cast<std::size_t>(i)]] = values[i];
}

Binding<Evaluator> MathematicalProgram::AddCost(std::shared_ptr<Evaluator> cost, const DecisionVariables& vars) {
  CheckVariables(vars, "AddCost");
  Binding<Evaluator> binding(std::move(cost), vars);
  if (binding.evaluator()->num_outputs() != 1) {
    throw std::invalid_argument("AddCost('" + binding.evaluator()->name() + "'): a cost must have exactly one "
                                "output but it has " + cairn::FormatShort(binding.evaluator()->num_outputs()) +
                                "; for a vector residual use AddLeastSquaresCost.");
  }
  costs_.push_back(binding);
  return binding;
}

Binding<LinearCost> MathematicalProgram::AddLinearCost(const Eigen::Ref<const Eigen::VectorXd>& a, double b,
                                                       const DecisionVariables& vars) {
  CheckVariables(vars, "AddLinearCost");
  Binding<LinearCost> binding(std::make_shared<LinearCost>(a, b), vars);
  costs_.emplace_back(binding);
  return binding;
}

Binding<QuadraticCost> MathematicalProgram::AddQuadraticCost(const Eigen::SparseMatrix<double>& Q,
                                                             const Eigen::Ref<const Eigen::VectorXd>& b, double c,
                                                             const DecisionVariables& vars) {
  CheckVariables(vars, "AddQuadraticCost");
  Binding<QuadraticCost> binding(std::make_shared<QuadraticCost>(Q, b, c), vars);
  costs_.emplace_back(binding);
  return binding;
}

Binding<Evaluator> MathematicalProgram::AddLeastSquaresCost(std::shared_ptr<Evaluator> residual,
                                                            const DecisionVariables& vars) {
  CheckVariables(vars, "AddLeastSquaresCost");
  Binding<Evaluator> binding(std::move(residual), vars);
  least_squares_costs_.push_back(binding);
  return binding;
}

Binding<Constraint> MathematicalProgram::AddConstraint(std::shared_ptr<Evaluator> function,
                                                       const Eigen::Ref<const Eigen::VectorXd>& lb,
                                                       const Eigen::Ref<const Eigen::VectorXd>& ub,
                                                       const DecisionVariables& vars) {
  CheckVariables(vars, "AddConstraint");
  return AddConstraint(std::make_shared<EvaluatorConstraint>(std::move(function), lb, ub), vars);
}

Binding<Constraint> MathematicalProgram::AddConstraint(std::shared_ptr<Constraint> constraint,
                                                       const DecisionVariables& vars) {
  CheckVariables(vars, "AddConstraint");
  Binding<Constraint> binding(std::move(constraint), vars);
  if (auto box = std::dynamic_pointer_cast<BoundingBoxConstraint>(binding.evaluator())) {
    bounding_boxes_.emplace_back(box, vars);
  } else {
    constraints_.push_back(binding);
  }
  return binding;
}

Binding<LinearConstraint> MathematicalProgram::AddLinearConstraint(const Eigen::SparseMatrix<double>& A,
                                                                   const Eigen::Ref<const Eigen::VectorXd>& lb,
                                                                   const Eigen::Ref<const Eigen::VectorXd>& ub,
                                                                   const DecisionVariables& vars) {
  CheckVariables(vars, "AddLinearConstraint");
  Binding<LinearConstraint> binding(std::make_shared<LinearConstraint>(A, lb, ub), vars);
  constraints_.emplace_back(binding);
  return binding;
}

Binding<LinearEqualityConstraint> MathematicalProgram::AddLinearEqualityConstraint(
    const Eigen::SparseMatrix<double>& A, const Eigen::Ref<const Eigen::VectorXd>& b, const DecisionVariables& vars) {
  CheckVariables(vars, "AddLinearEqualityConstraint");
  Binding<LinearEqualityConstraint> binding(std::make_shared<LinearEqualityConstraint>(A, b), vars);
  constraints_.emplace_back(binding);
  return binding;
}

Binding<BoundingBoxConstraint> MathematicalProgram::AddBoundingBoxConstraint(
    const Eigen::Ref<const Eigen::VectorXd>& lb, const Eigen::Ref<const Eigen::VectorXd>& ub,
    const DecisionVariables& vars) {
  CheckVariables(vars, "AddBoundingBoxConstraint");
  Binding<BoundingBoxConstraint> binding(std::make_shared<BoundingBoxConstraint>(lb, ub), vars);
  bounding_boxes_.push_back(binding);
  return binding;
}

Binding<BoundingBoxConstraint> MathematicalProgram::AddBoundingBoxConstraint(double lb, double ub,
                                                                             const DecisionVariables& vars) {
  return AddBoundingBoxConstraint(Eigen::VectorXd::Constant(vars.size(), lb),
                                  Eigen::VectorXd::Constant(vars.size(), ub), vars);
}

Eigen::VectorXd MathematicalProgram::variable_lower_bounds() const {
  Eigen::VectorXd lower = Eigen::VectorXd::Constant(num_vars(), -std::numeric_limits<double>::infinity());
  for (const auto& box : bounding_boxes_) {
    const std::vector<int>& indices = box.variables().indices();
    for (std::size_t i = 0; i < indices.size(); ++i) {
      lower[indices[i]] = std::max(lower[indices[i]], box.evaluator()->lower_bound()[static_cast<Eigen::Index>(i)]);
    }
  }
  return lower;
}

Eigen::VectorXd MathematicalProgram::variable_upper_bounds() const {
  Eigen::VectorXd upper = Eigen::VectorXd::Constant(num_vars(), std::numeric_limits<double>::infinity());
  for (const auto& box : bounding_boxes_) {
    const std::vector<int>& indices = box.variables().indices();
    for (std::size_t i = 0; i < indices.size(); ++i) {
      upper[indices[i]] = std::min(upper[indices[i]], box.evaluator()->upper_bound()[static_cast<Eigen::Index>(i)]);
    }
  }
  return upper;
}

double MathematicalProgram::EvalCost(const Eigen::Ref<const Eigen::VectorXd>& x) const {
  CheckDecisionVectorSize(x, "EvalCost");
  double total = 0.0;
  Eigen::VectorXd local;
  for (const auto& cost : costs_) {
    local.resize(cost.variables().size());
    for (int i = 0; i < local.size(); ++i) local[i] = x[cost.variables().indices()[static_cast<std::size_t>(i)]];
    total += cost.evaluator()->Eval(local)[0];
  }
  for (const auto& cost : least_squares_costs_) {
    local.resize(cost.variables().size());
    for (int i = 0; i < local.size(); ++i) local[i] = x[cost.variables().indices()[static_cast<std::size_t>(i)]];
    total += 0.5 * cost.evaluator()->Eval(local).squaredNorm();
  }
  return total;
}

}  // namespace cairn::optimization
