#include "cairn/common/number_text.h"
#include "cairn/optimization/check_gradients.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace cairn::optimization {

namespace {

const double kRelativeStep = std::cbrt(std::numeric_limits<double>::epsilon());

double Error(double analytic, double fd) { return std::abs(analytic - fd) / std::max(1.0, std::abs(fd)); }

template <typename E>
void CheckBinding(const MathematicalProgram& prog, const Binding<E>& binding, const std::string& kind,
                  const Eigen::Ref<const Eigen::VectorXd>& x, std::vector<GradientCheckResult::Entry>* entries) {
  const Evaluator& f = *binding.evaluator();
  const std::vector<int>& indices = binding.variables().indices();
  const int n = f.num_inputs();
  const int m = f.num_outputs();
  Eigen::VectorXd local(n);
  for (int i = 0; i < n; ++i) local[i] = x[indices[static_cast<std::size_t>(i)]];

  const Eigen::MatrixXd analytic = Eigen::MatrixXd(f.EvalJacobian(local));
  Eigen::MatrixXd in_pattern = Eigen::MatrixXd::Zero(m, n);
  for (const SparsityEntry& e : f.jacobian_pattern()) in_pattern(e.row, e.col) = 1.0;
  Eigen::VectorXd perturbed = local, y_plus(m), y_minus(m);
  for (int j = 0; j < n; ++j) {
    const double h = kRelativeStep * std::max(1.0, std::abs(local[j]));
    perturbed[j] = local[j] + h;
    f.Eval(perturbed, y_plus);
    perturbed[j] = local[j] - h;
    f.Eval(perturbed, y_minus);
    perturbed[j] = local[j];
    for (int r = 0; r < m; ++r) {
      GradientCheckResult::Entry entry;
      entry.term = binding.ToString();
      entry.kind = kind;
      entry.output = r;
      entry.variable = prog.VariableName(indices[static_cast<std::size_t>(j)]);
      entry.analytic = analytic(r, j);
      entry.finite_difference = (y_plus[r] - y_minus[r]) / (2.0 * h);
      entry.error = Error(entry.analytic, entry.finite_difference);
      entry.in_pattern = in_pattern(r, j) != 0.0;
      entry.source = f.jacobian_source();
      entries->push_back(entry);
    }
  }

  if (!f.has_hessian()) return;
  Eigen::VectorXd weights(m);
  for (int r = 0; r < m; ++r) weights[r] = 1.0 + 0.1 * r;
  Eigen::VectorXd hessian_values(static_cast<Eigen::Index>(f.hessian_pattern().size()));
  f.EvalHessian(local, weights, hessian_values);
  Eigen::MatrixXd hessian = Eigen::MatrixXd::Zero(n, n);
  Eigen::MatrixXd hessian_pattern = Eigen::MatrixXd::Zero(n, n);
  for (std::size_t k = 0; k < f.hessian_pattern().size(); ++k) {
    const SparsityEntry& e = f.hessian_pattern()[k];
    hessian(e.row, e.col) = hessian_values[static_cast<Eigen::Index>(k)];
    hessian_pattern(e.row, e.col) = 1.0;
  }
  // Column j of the weighted Hessian is the derivative of the weighted gradient J' w along x_j.
  for (int j = 0; j < n; ++j) {
    const double h = kRelativeStep * std::max(1.0, std::abs(local[j]));
    perturbed[j] = local[j] + h;
    const Eigen::VectorXd g_plus = Eigen::MatrixXd(f.EvalJacobian(perturbed)).transpose() * weights;
    perturbed[j] = local[j] - h;
    const Eigen::VectorXd g_minus = Eigen::MatrixXd(f.EvalJacobian(perturbed)).transpose() * weights;
    perturbed[j] = local[j];
    for (int i = j; i < n; ++i) {
      GradientCheckResult::Entry entry;
      entry.term = binding.ToString();
      entry.kind = kind + " Hessian";
      entry.output = i;
      entry.row_variable = prog.VariableName(indices[static_cast<std::size_t>(i)]);
      entry.variable = prog.VariableName(indices[static_cast<std::size_t>(j)]);
      entry.analytic = hessian(i, j);
      entry.finite_difference = (g_plus[i] - g_minus[i]) / (2.0 * h);
      entry.error = Error(entry.analytic, entry.finite_difference);
      entry.in_pattern = hessian_pattern(i, j) != 0.0;
      entry.source = DerivativeSource::kAnalytic;
      entries->push_back(entry);
    }
  }
}

}  // namespace

std::string GradientCheckResult::ToString() const {
  std::ostringstream out;
  out << "CheckGradients: " << (passed ? "passed" : "FAILED") << ", " << num_failed << " of " << num_checked
      << " entries exceed the tolerance " << tolerance << " (max error " << max_error << ")";
  for (const Entry& e : worst_entries) {
    out << "\n  " << e.kind << " '" << e.term << "' ";
    if (e.row_variable.empty()) {
      out << "d(output " << e.output << ")/d(" << e.variable << ")";
    } else {
      out << "d2/d(" << e.row_variable << ")d(" << e.variable << ")";
    }
    out << ": " << (e.in_pattern ? "" : "missing from the declared pattern, ") << "evaluator " << e.analytic
        << " [" << to_string(e.source) << "], finite difference " << e.finite_difference << ", error " << e.error;
  }
  return out.str();
}

namespace {

void CheckTolerance(double tolerance) {
  if (!(tolerance > 0.0)) {
    throw std::invalid_argument("CheckGradients: tolerance = " + cairn::FormatShort(tolerance) +
                                " must be positive (1e-5 suits central differences).");
  }
}

GradientCheckResult Summarise(std::vector<GradientCheckResult::Entry> entries, double tolerance, int max_reported) {
  GradientCheckResult result;
  result.tolerance = tolerance;
  result.num_checked = static_cast<int>(entries.size());
  std::stable_sort(entries.begin(), entries.end(),
                   [](const GradientCheckResult::Entry& a, const GradientCheckResult::Entry& b) {
                     return a.error > b.error;
                   });
  for (const auto& e : entries) {
    result.max_error = std::max(result.max_error, e.error);
    if (!(e.error <= tolerance)) ++result.num_failed;
  }
  result.passed = result.num_failed == 0;
  for (std::size_t i = 0; i < entries.size() && static_cast<int>(i) < max_reported; ++i) {
    if (entries[i].error <= tolerance && !result.passed) break;
    result.worst_entries.push_back(entries[i]);
  }
  return result;
}

}  // namespace

GradientCheckResult CheckGradients(const MathematicalProgram& prog, const Eigen::Ref<const Eigen::VectorXd>& x,
                                   double tolerance, int max_reported) {
  if (x.size() != prog.num_vars()) {
    throw std::invalid_argument("CheckGradients: x has size " + cairn::FormatShort(x.size()) + " but the program has " +
                                cairn::FormatShort(prog.num_vars()) + " variables; pass one value per variable.");
  }
  CheckTolerance(tolerance);
  std::vector<GradientCheckResult::Entry> entries;
  for (const auto& b : prog.costs()) CheckBinding(prog, b, "cost", x, &entries);
  for (const auto& b : prog.least_squares_costs()) CheckBinding(prog, b, "least-squares residual", x, &entries);
  for (const auto& b : prog.constraints()) CheckBinding(prog, b, "constraint", x, &entries);
  return Summarise(std::move(entries), tolerance, max_reported);
}

GradientCheckResult CheckGradients(const Evaluator& evaluator, const Eigen::Ref<const Eigen::VectorXd>& x,
                                   double tolerance, int max_reported) {
  if (x.size() != evaluator.num_inputs()) {
    throw std::invalid_argument("CheckGradients: x has size " + cairn::FormatShort(x.size()) + " but evaluator '" +
                                evaluator.name() + "' takes " + cairn::FormatShort(evaluator.num_inputs()) +
                                " inputs.");
  }
  CheckTolerance(tolerance);
  MathematicalProgram prog;
  std::vector<GradientCheckResult::Entry> entries;
  if (evaluator.num_inputs() > 0) {
    const DecisionVariables vars = prog.NewContinuousVariables(evaluator.num_inputs(), "x");
    // A non-owning pointer: the binding lives only inside this call.
    const std::shared_ptr<const Evaluator> borrowed(std::shared_ptr<const Evaluator>(), &evaluator);
    const Binding<const Evaluator> binding(borrowed, vars);
    CheckBinding(prog, binding, "evaluator", x, &entries);
  }
  return Summarise(std::move(entries), tolerance, max_reported);
}

}  // namespace cairn::optimization
