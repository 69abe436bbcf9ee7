#pragma once

#include <string>
#include <vector>

#include <Eigen/Core>

#include "cairn/optimization/mathematical_program.h"

namespace cairn::optimization {

/// The solver-facing view of a MathematicalProgram: every term's variables flattened, constraint rows stacked
/// (bounding boxes folded into variable bounds), and the global sparse structures -- constraint Jacobian
/// triplets and the Lagrangian Hessian's lower triangle -- assembled once at construction.
///
/// Evaluation methods take and fill raw arrays in the solvers' layout and do not allocate: every term writes
/// into preallocated slices (constraint values and Jacobian values go straight into the caller's arrays, in
/// the triplet order of jacobian_rows()/jacobian_cols()). An assembly holds mutable scratch space, so use one
/// per solve (or per thread); the program itself is only read.
class ProgramAssembly {
 public:
  /// How the Hessian of a least-squares cost 1/2 ||r(x)||^2 is formed.
  enum class LeastSquaresHessian {
    /// J'J + sum_k r_k Hessian(r_k): needs the residual's Hessian.
    kExact,
    /// J'J alone (Gauss-Newton): positive semidefinite, costs nothing beyond the residual Jacobian, and needs no
    /// residual Hessian. Close to the exact Hessian where the residuals are small or nearly linear; it drops
    /// their curvature, so Newton's quadratic convergence becomes linear near a solution with large residuals.
    kGaussNewton,
  };

  /// Builds the structures for `prog`, which must outlive the assembly.
  explicit ProgramAssembly(const MathematicalProgram& prog,
                           LeastSquaresHessian least_squares_hessian = LeastSquaresHessian::kExact);

  /// The program this assembly reads.
  const MathematicalProgram& program() const { return *prog_; }
  /// Number of decision variables.
  int num_vars() const { return num_vars_; }
  /// Number of stacked constraint rows (bounding boxes excluded).
  int num_constraints() const { return num_rows_; }
  /// Variable bounds (the bounding boxes' intersection).
  const Eigen::VectorXd& variable_lower_bounds() const { return x_lower_; }
  /// Variable bounds (the bounding boxes' intersection).
  const Eigen::VectorXd& variable_upper_bounds() const { return x_upper_; }
  /// Stacked constraint lower bounds.
  const Eigen::VectorXd& constraint_lower_bounds() const { return g_lower_; }
  /// Stacked constraint upper bounds.
  const Eigen::VectorXd& constraint_upper_bounds() const { return g_upper_; }
  /// First stacked row of prog.constraints()[i].
  int constraint_row_offset(int i) const { return constraint_terms_[static_cast<std::size_t>(i)].row_offset; }

  /// Jacobian triplet rows (into the stacked constraint vector).
  const std::vector<int>& jacobian_rows() const { return jacobian_rows_; }
  /// Jacobian triplet columns (decision-variable indices).
  const std::vector<int>& jacobian_cols() const { return jacobian_cols_; }
  /// Number of Jacobian nonzeros.
  int jacobian_nonzeros() const { return static_cast<int>(jacobian_rows_.size()); }

  /// True if every cost and constraint provides a Hessian. A least-squares cost provides one when its residual
  /// does (its Hessian is J'J + sum_k r_k Hessian(r_k)); a linear residual declares an empty Hessian pattern.
  /// With LeastSquaresHessian::kGaussNewton every least-squares cost provides one (J'J).
  bool has_hessian() const { return has_hessian_; }
  /// Lower-triangle Hessian rows (row >= col), unique entries.
  const std::vector<int>& hessian_rows() const { return hessian_rows_; }
  /// Lower-triangle Hessian columns.
  const std::vector<int>& hessian_cols() const { return hessian_cols_; }

  /// Number of stacked least-squares residual rows.
  int num_residuals() const { return num_residuals_; }
  /// Residual Jacobian triplet rows (into the stacked residual vector).
  const std::vector<int>& residual_jacobian_rows() const { return residual_rows_; }
  /// Residual Jacobian triplet columns (decision-variable indices).
  const std::vector<int>& residual_jacobian_cols() const { return residual_cols_; }
  /// Stacked least-squares residuals r(x) (the objective's least-squares part is 1/2 ||r||^2).
  void EvalResiduals(const double* x, double* r);
  /// Stacked residuals and their Jacobian values in residual triplet order.
  void EvalResidualsAndJacobian(const double* x, double* r, double* jacobian_values);

  /// Objective value at x.
  double EvalCost(const double* x);
  /// Objective value at x and its dense gradient.
  double EvalCostAndGradient(const double* x, double* gradient);
  /// Stacked constraint values g(x).
  void EvalConstraints(const double* x, double* g);
  /// Stacked constraint values and the Jacobian values in triplet order (g may be null to skip the values).
  void EvalConstraintsAndJacobian(const double* x, double* g, double* jacobian_values);
  /// objective_factor * Hessian(cost) + sum_i lambda_i Hessian(g_i), in hessian_rows()/cols() order. Requires
  /// has_hessian().
  void EvalLagrangianHessian(const double* x, double objective_factor, const double* lambda, double* values);

  /// Largest violation of the constraints and the variable bounds at x (0 if feasible).
  double ConstraintViolation(const double* x);
  /// Describes where ConstraintViolation's maximum occurs, e.g. "constraint 'hs071_product(x)' row 0 (value
  /// 24.1, bounds [25, inf])", or "" if x is feasible.
  std::string DescribeWorstViolation(const double* x);

 private:
  struct Term {
    const Evaluator* evaluator{nullptr};
    int var_offset{0};   // into var_indices_
    int num_inputs{0};
    int x_offset{0};     // into x_local_
    int y_offset{0};     // into y_local_ (costs) -- constraints use row_offset into the caller's g
    int jac_offset{0};   // into jac_local_ (costs) or the caller's Jacobian values (constraints)
    int row_offset{0};   // constraints: first stacked row; least squares: first stacked residual
    int residual_jac_offset{0};  // least squares: first entry in the residual Jacobian triplets
    int hess_offset{0};  // into hess_local_ and hess_map_
    std::vector<SparsityEntry> hess_pattern;  // local lower-triangle Hessian pattern of this term
    int ls_pair_offset{0};        // least squares: J'J products in ls_pairs_
    int ls_pair_count{0};
    int residual_hess_offset{0};  // least squares: residual Hessian entries in ls_residual_hess_map_
  };
  struct LeastSquaresPair {
    int a, b, local;  // hess_local[local] += J[a] * J[b]
  };

  void Gather(const Term& term, const double* x);

  const MathematicalProgram* prog_;
  LeastSquaresHessian least_squares_hessian_;
  int num_vars_{0};
  int num_rows_{0};
  int num_residuals_{0};
  std::vector<int> residual_rows_, residual_cols_;
  Eigen::VectorXd x_lower_, x_upper_, g_lower_, g_upper_;
  std::vector<int> var_indices_;
  std::vector<Term> cost_terms_;
  std::vector<Term> least_squares_terms_;
  std::vector<Term> constraint_terms_;
  Eigen::VectorXd x_local_, y_local_, jac_local_, hess_local_, g_scratch_;
  std::vector<int> jacobian_rows_, jacobian_cols_;
  bool has_hessian_{false};
  std::vector<int> hessian_rows_, hessian_cols_;
  std::vector<int> hess_map_;  // local Hessian entry -> global Hessian value index
  std::vector<LeastSquaresPair> ls_pairs_;
  std::vector<int> ls_residual_hess_map_;  // residual Hessian entry -> local Hessian entry of its term
  Eigen::VectorXd residual_hess_local_;
};

}  // namespace cairn::optimization
