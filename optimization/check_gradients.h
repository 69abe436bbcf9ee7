#pragma once

#include <string>
#include <vector>

#include <Eigen/Core>

#include "cairn/optimization/mathematical_program.h"

namespace cairn::optimization {

/// The outcome of CheckGradients: how well every cost's and constraint's Jacobian (and declared Hessian) agrees
/// with central finite differences of its values at one point.
struct GradientCheckResult {
  /// One compared derivative entry.
  struct Entry {
    std::string term;          ///< Binding label, e.g. "hs071_product(x)".
    std::string kind;          ///< "cost", "least-squares residual", "constraint", or the same with " Hessian".
    int output{0};             ///< Output row of the evaluator (or Hessian row variable, local).
    std::string variable;      ///< Program variable of the column, e.g. "x(2)".
    std::string row_variable;  ///< For Hessian entries: the program variable of the row; empty otherwise.
    double analytic{0.0};      ///< The evaluator's value (0 if the entry is outside its declared pattern).
    double finite_difference{0.0};  ///< Central finite-difference estimate.
    double error{0.0};         ///< |analytic - finite_difference| / max(1, |finite_difference|).
    bool in_pattern{true};     ///< False if the evaluator's pattern omits an entry that is numerically nonzero.
    DerivativeSource source{DerivativeSource::kAnalytic};  ///< Where the evaluator's derivatives come from.
  };

  /// True if every error is within the tolerance.
  bool passed{true};
  /// The largest error seen.
  double max_error{0.0};
  /// Number of entries compared.
  int num_checked{0};
  /// Number of entries above the tolerance.
  int num_failed{0};
  /// The tolerance used.
  double tolerance{0.0};
  /// The worst entries (largest error first), at most the requested number.
  std::vector<Entry> worst_entries;

  /// A readable report naming the worst entries by term and variable.
  std::string ToString() const;
};

/// Compares every analytic (or autodiff) Jacobian of `prog`'s costs, least-squares residuals and constraints at
/// `x` with central finite differences of the evaluators' values, over all (output, variable) pairs, so an
/// entry missing from a declared pattern is caught too; evaluators that declare a Hessian have it compared with
/// differences of their weighted gradients (weights 1, 1.1, 1.2, ...). Bounding boxes are exact and skipped.
/// Throws std::invalid_argument if x has the wrong size.
GradientCheckResult CheckGradients(const MathematicalProgram& prog, const Eigen::Ref<const Eigen::VectorXd>& x,
                                   double tolerance = 1e-5, int max_reported = 10);

/// The same check for one evaluator on its own (inputs named x(0), x(1), ...; kind "evaluator"), for unit tests
/// of evaluators before they are bound into a program.
GradientCheckResult CheckGradients(const Evaluator& evaluator, const Eigen::Ref<const Eigen::VectorXd>& x,
                                   double tolerance = 1e-5, int max_reported = 10);

}  // namespace cairn::optimization
