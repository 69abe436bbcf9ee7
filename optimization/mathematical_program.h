#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include "cairn/optimization/binding.h"
#include "cairn/optimization/bounding_box_constraint.h"
#include "cairn/optimization/constraint.h"
#include "cairn/optimization/decision_variables.h"
#include "cairn/optimization/evaluator.h"
#include "cairn/optimization/linear_constraint.h"
#include "cairn/optimization/linear_cost.h"
#include "cairn/optimization/linear_equality_constraint.h"
#include "cairn/optimization/quadratic_cost.h"

namespace cairn::optimization {

/// An optimisation problem: minimise the sum of the costs over the decision variables subject to every
/// constraint lb <= f(x) <= ub.
///
/// Build it by creating variables (NewContinuousVariables) and binding costs and constraints to them; then hand it
/// to a solver (Solve(prog), MakeSolver("ipopt")->Solve(...), ...). Four kinds of terms:
/// - costs: any scalar Evaluator (AddCost), LinearCost, QuadraticCost;
/// - least-squares costs 1/2 ||r(x)||^2 (AddLeastSquaresCost), which LeastSquaresSolver exploits and every other
///   solver treats as ordinary costs;
/// - bounding boxes (AddBoundingBoxConstraint), which solvers fold into their variable bounds;
/// - constraints: linear (sparse A), linear equalities, and generic nonlinear evaluators with bounds.
/// Evaluators are shared, immutable objects; the program only records which variables feed them. Solving never
/// modifies the program, so one program may be solved by several solvers or threads at once.
class MathematicalProgram {
 public:
  /// An empty program.
  MathematicalProgram();

  /// Adds `n` continuous variables named name(0) .. name(n-1) (just `name` if n == 1), initial guess 0 and no
  /// bounds. Throws std::invalid_argument if n < 1, the name is empty or another block already has this name.
  DecisionVariables NewContinuousVariables(int n, const std::string& name);

  /// Number of decision variables.
  int num_vars() const { return static_cast<int>(variable_names_.size()); }

  /// Name of the variable at `index` in the decision vector, e.g. "q(3)".
  const std::string& VariableName(int index) const;

  /// Every variable block created so far, in creation order.
  const std::vector<DecisionVariables>& variable_blocks() const { return blocks_; }

  /// Looks a block up by the name given to NewContinuousVariables; throws std::invalid_argument with the closest
  /// names if there is none.
  const DecisionVariables& GetVariables(const std::string& name) const;

  /// Sets the initial guess of `vars` (one value per variable).
  void SetInitialGuess(const DecisionVariables& vars, const Eigen::Ref<const Eigen::VectorXd>& values);

  /// The initial guess of every variable (0 unless set).
  const Eigen::VectorXd& initial_guess() const { return initial_guess_; }

  /// Adds a scalar cost. Throws std::invalid_argument if `cost` does not have exactly one output.
  Binding<Evaluator> AddCost(std::shared_ptr<Evaluator> cost, const DecisionVariables& vars);

  /// Adds the cost a'x + b over `vars`.
  Binding<LinearCost> AddLinearCost(const Eigen::Ref<const Eigen::VectorXd>& a, double b,
                                    const DecisionVariables& vars);

  /// Adds the cost 1/2 x'Qx + b'x + c over `vars` (Q sparse and symmetric).
  Binding<QuadraticCost> AddQuadraticCost(const Eigen::SparseMatrix<double>& Q,
                                          const Eigen::Ref<const Eigen::VectorXd>& b, double c,
                                          const DecisionVariables& vars);

  /// Adds the cost 1/2 ||r(x)||^2 for the residual evaluator `residual` bound to `vars`. If the residual declares a
  /// Hessian (sum_k w_k Hessian(r_k), empty for linear residuals), general solvers get the exact Hessian
  /// J'J + sum_k r_k Hessian(r_k); otherwise Ipopt falls back to L-BFGS.
  Binding<Evaluator> AddLeastSquaresCost(std::shared_ptr<Evaluator> residual, const DecisionVariables& vars);

  /// Adds lb <= f(x) <= ub for a generic evaluator f.
  Binding<Constraint> AddConstraint(std::shared_ptr<Evaluator> function, const Eigen::Ref<const Eigen::VectorXd>& lb,
                                    const Eigen::Ref<const Eigen::VectorXd>& ub, const DecisionVariables& vars);

  /// Adds an already-built constraint (a BoundingBoxConstraint goes to the bounding boxes).
  Binding<Constraint> AddConstraint(std::shared_ptr<Constraint> constraint, const DecisionVariables& vars);

  /// Adds lb <= A x <= ub.
  Binding<LinearConstraint> AddLinearConstraint(const Eigen::SparseMatrix<double>& A,
                                                const Eigen::Ref<const Eigen::VectorXd>& lb,
                                                const Eigen::Ref<const Eigen::VectorXd>& ub,
                                                const DecisionVariables& vars);

  /// Adds A x = b.
  Binding<LinearEqualityConstraint> AddLinearEqualityConstraint(const Eigen::SparseMatrix<double>& A,
                                                                const Eigen::Ref<const Eigen::VectorXd>& b,
                                                                const DecisionVariables& vars);

  /// Adds lb <= x <= ub on `vars`.
  Binding<BoundingBoxConstraint> AddBoundingBoxConstraint(const Eigen::Ref<const Eigen::VectorXd>& lb,
                                                          const Eigen::Ref<const Eigen::VectorXd>& ub,
                                                          const DecisionVariables& vars);

  /// Adds lb <= x_i <= ub for every variable of `vars`.
  Binding<BoundingBoxConstraint> AddBoundingBoxConstraint(double lb, double ub, const DecisionVariables& vars);

  /// Scalar costs (generic, linear, quadratic), in insertion order.
  const std::vector<Binding<Evaluator>>& costs() const { return costs_; }
  /// Residuals of least-squares costs, in insertion order.
  const std::vector<Binding<Evaluator>>& least_squares_costs() const { return least_squares_costs_; }
  /// Constraints other than bounding boxes, in insertion order (their rows are stacked in this order).
  const std::vector<Binding<Constraint>>& constraints() const { return constraints_; }
  /// Bounding boxes, in insertion order.
  const std::vector<Binding<BoundingBoxConstraint>>& bounding_box_constraints() const { return bounding_boxes_; }

  /// Per-variable lower bounds: the intersection of every bounding box (-infinity where none applies).
  Eigen::VectorXd variable_lower_bounds() const;
  /// Per-variable upper bounds: the intersection of every bounding box (+infinity where none applies).
  Eigen::VectorXd variable_upper_bounds() const;

  /// The objective at x: the sum of the costs plus 1/2 ||r||^2 for every least-squares cost.
  double EvalCost(const Eigen::Ref<const Eigen::VectorXd>& x) const;

  /// Identifier that DecisionVariables carry to prove they belong to this program.
  std::int64_t id() const { return id_; }

 private:
  void CheckVariables(const DecisionVariables& vars, const std::string& what) const;
  void CheckDecisionVectorSize(const Eigen::Ref<const Eigen::VectorXd>& x, const char* method) const;

  std::int64_t id_;
  std::vector<std::string> variable_names_;
  std::vector<DecisionVariables> blocks_;
  Eigen::VectorXd initial_guess_;
  std::vector<Binding<Evaluator>> costs_;
  std::vector<Binding<Evaluator>> least_squares_costs_;
  std::vector<Binding<Constraint>> constraints_;
  std::vector<Binding<BoundingBoxConstraint>> bounding_boxes_;
};

}  // namespace cairn::optimization
